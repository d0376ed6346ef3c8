// The start of every layout pass: options checked, the printable area, the strips scaled.
#include "nodes/layout/prepare_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "core/errors.h"
#include "nodes/layout/format_mm.h"
#include "nodes/layout/pages.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft {
namespace layout_internal {

void validate_options(const LayoutOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v))
      throw InvalidInputException(std::string("layout option ") + name + " must be > 0");
  };
  auto non_negative = [](double v, const char* name) {
    if (!(v >= 0) || !std::isfinite(v))
      throw InvalidInputException(std::string("layout option ") + name + " must be >= 0");
  };
  positive(o.page.width_mm, "page width");
  positive(o.page.height_mm, "page height");
  non_negative(o.margin_mm, "margin_mm");
  non_negative(o.height_mm, "height_mm");
  non_negative(o.scale, "scale");
  non_negative(o.tab_width_mm, "tab_width_mm");
  non_negative(o.fold_angle_degrees, "fold_angle_degrees");
  non_negative(o.strong_fold_angle_degrees, "strong_fold_angle_degrees");
  non_negative(o.spacing_mm, "spacing_mm");
  positive(o.label_size_mm, "label_size_mm");
  positive(o.number_size_mm, "number_size_mm");
  non_negative(o.footer_mm, "footer_mm");
  if (!(o.tab_angle_degrees > 0 && o.tab_angle_degrees <= 90))
    throw InvalidInputException("layout option tab_angle_degrees must be in (0, 90]");
  positive(o.alternate_run_mm, "alternate_run_mm");
  if (!(o.scale > 0) && !(o.height_mm > 0))
    throw InvalidInputException("layout needs height_mm > 0 or scale > 0");
  if (o.splits_per_page < 1)
    throw InvalidInputException("layout option splits_per_page must be >= 1");
}

double tab_reserve_for(const LayoutOptions& o) {
  return o.tab_style == TabStyle::None ? 0.0 : 1.15 * o.tab_width_mm;
}

Vec2 usable_area(const LayoutOptions& o) {
  const double footer = o.footer_mm > 0 ? o.footer_mm + o.spacing_mm : 0.0;
  const Vec2 area(o.page.width_mm - 2 * o.margin_mm, o.page.height_mm - 2 * o.margin_mm - footer);
  const double reserve = 2 * tab_reserve_for(o);
  if (area.x() - reserve < 1.0 || area.y() - reserve < 1.0)
    throw InvalidInputException("page " + format_mm(o.page.width_mm) + " x " +
                                format_mm(o.page.height_mm) +
                                " mm leaves no room inside margins "
                                "of " +
                                format_mm(o.margin_mm) + " mm for pieces with tabs");
  return area;
}

}  // namespace layout_internal

double layout_scale(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  layout_internal::validate_options(options);
  if (options.scale > 0) return options.scale;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const FlatStrip& strip : strips)
    for (const Vec3& v : strip.vertices3d) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  const double side = (hi - lo).maxCoeff();
  if (!(side > 0) || !std::isfinite(side))
    throw InvalidInputException(
        "cannot scale the strips to height_mm: their 3D bounding box has no extent (give a "
        "scale in mm per model unit instead)");
  return options.height_mm / side;
}

namespace layout_internal {

PreparedLayout prepare_layout(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  validate_options(options);
  std::set<int> ids;
  for (const FlatStrip& strip : strips) {
    validate_strip(strip);
    if (!ids.insert(strip.id).second)
      throw InvalidInputException("two strips have id " + std::to_string(strip.id));
  }
  PreparedLayout p;
  p.area = usable_area(options);
  p.reserve = tab_reserve_for(options);
  if (strips.empty()) {
    p.mm_per_unit = options.scale > 0 ? options.scale : 1.0;
    return p;
  }
  p.mm_per_unit = layout_scale(strips, options);
  double largest = 0;
  for (const FlatStrip& strip : strips)
    for (const Vec3& v : strip.vertices3d) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  p.tolerance3d = 1e-9 * std::max(largest, 1e-300);
  for (const FlatStrip& strip : strips) p.strips.push_back(prepare_strip(strip, p.mm_per_unit));
  return p;
}

bool strip_fits(const StripData& data, const PreparedLayout& p, const std::vector<int>& triangles) {
  return hull_fits(convex_hull(piece_points(data, triangles)), p.area.x() - 2 * p.reserve,
                   p.area.y() - 2 * p.reserve);
}

bool strip_fits(const StripData& data, const PreparedLayout& p) {
  return strip_fits(data, p, data.triangles);
}

}  // namespace layout_internal
}  // namespace papercraft
