#include "core/piece_limits.h"

#include <algorithm>

#include "core/piece_width.h"

namespace papercraft {

double piece_shortfall(const Mesh& piece, const PieceLimits& limits) {
  if (!limits.active()) return 0.0;
  double shortfall = 0.0;
  const double area = surface_area(piece);
  if (limits.min_area > 0.0 && area < limits.min_area) shortfall = 1.0 - area / limits.min_area;
  if (limits.min_width > 0.0) {
    // A coarse raster: the judgement is about tips against bands, not the last percent.
    PieceWidthOptions options;
    options.cell_fraction = 0.25;
    options.max_cells = 100'000;
    const TriangleMesh mesh = to_triangle_mesh(piece);
    const double narrow = narrow_area_fraction(mesh, limits.min_width, options);
    if (narrow > limits.max_narrow_share)
      shortfall =
          std::max(shortfall, (narrow - limits.max_narrow_share) / (1.0 - limits.max_narrow_share));
    const double width = limits.sliver_width * limits.min_width;
    const double most = limits.max_sliver_area * width * width;
    // What is narrower than sliver_width is narrower than min_width too (a smaller disc fits
    // wherever a larger one does): a piece narrow at min_width over less than the bound has
    // no sliver to look for, and most pieces are that.
    if (most > 0.0 && narrow * area > most) {
      const double sliver = narrow_measure(mesh, width, options).largest_region;
      if (sliver > most) shortfall = std::max(shortfall, 1.0 - most / sliver);
    }
  }
  return shortfall;
}

bool piece_fits(const Mesh& piece, const PieceLimits& limits) {
  return piece_shortfall(piece, limits) == 0.0;
}

}  // namespace papercraft
