#pragma once
// Sheets of paper by name: the layout's `page` parameter, read also where the printable area
// of a page matters before any layout is made (the runner's page limit per model).

#include <string>
#include <string_view>

namespace papercraft {

/// A sheet of paper in millimetres.
struct PageSize {
  double width_mm = 210.0;
  double height_mm = 297.0;
};

/// "A3", "A4", "A5", "Letter", "Legal", "Tabloid" (case-insensitive) or "<width>x<height>"
/// in millimetres ("200x300"); portrait.
/// \throws InvalidInputException for any other name or a non-positive size.
PageSize page_size_from_name(std::string_view name);

/// The name page_size_from_name reads back: "A4" for the named sizes, else "200x300".
std::string page_size_name(const PageSize& page);

}  // namespace papercraft
