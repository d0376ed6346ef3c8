#pragma once
// What every layout pass starts from: the options checked, the printable area, the room kept
// for tabs, and the strips scaled to millimetres (StripData).

#include <vector>

#include "core/strip.h"
#include "nodes/layout/layout_types.h"
#include "nodes/layout/pieces.h"

namespace papercraft::layout_internal {

/// \throws InvalidInputException naming the first option out of range.
void validate_options(const LayoutOptions& options);

/// Room kept around a piece for its tabs while splitting: a flap stays within its height of
/// the seam but for the mitres at joints of up to 15 degrees and its short angled ends.
double tab_reserve_for(const LayoutOptions& options);

/// The printable area less the footer (and the gap above it).
/// \throws InvalidInputException where it leaves no room for pieces with tabs.
Vec2 usable_area(const LayoutOptions& options);

/// The strips of one layout pass in millimetres, with the area they are laid out on.
struct PreparedLayout {
  double mm_per_unit = 1;
  Vec2 area = Vec2::Zero();
  double reserve = 0;      // tab_reserve_for
  double tolerance3d = 0;  // 3D points this close are one (seam pairing)
  std::vector<StripData> strips;
};

/// The strips checked (validate_strip, unique ids) and scaled (layout_scale).
/// \throws InvalidInputException as layout_pages does.
PreparedLayout prepare_layout(const std::vector<FlatStrip>& strips, const LayoutOptions& options);

/// Whether `triangles` of the strip fit the area, less the tab reserve, in some orientation.
bool strip_fits(const StripData& data, const PreparedLayout& p, const std::vector<int>& triangles);

/// Whether the whole strip fits (strip_fits of its usable triangles).
bool strip_fits(const StripData& data, const PreparedLayout& p);

}  // namespace papercraft::layout_internal
