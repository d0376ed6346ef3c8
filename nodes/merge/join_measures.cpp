// Measures of a join: the slit a hinge leaves, and the narrow shares before and after.
#include "nodes/merge/join_measures.h"

#include <algorithm>
#include <array>
#include <limits>

namespace papercraft::merge_detail {

int slit_points(const FlatStrip& merged, std::size_t first_added, double width) {
  // The added points by 3D point (a join adds few), then one pass over the first strip's.
  std::map<std::array<double, 3>, std::vector<int>> added;
  for (std::size_t v = first_added; v < merged.vertices2d.size(); ++v) {
    const Vec3& p = merged.vertices3d[v];
    added[{p.x(), p.y(), p.z()}].push_back(static_cast<int>(v));
  }
  std::vector<char> slit(merged.vertices2d.size(), 0);
  for (std::size_t u = 0; u < first_added && !added.empty(); ++u) {
    const Vec3& p = merged.vertices3d[u];
    auto it = added.find({p.x(), p.y(), p.z()});
    if (it == added.end()) continue;
    for (int v : it->second)
      if ((merged.vertices2d[u] - merged.vertices2d[v]).norm() < width) slit[v] = 1;
  }
  return static_cast<int>(std::count(slit.begin(), slit.end(), 1));
}

std::pair<double, double> shares_before_and_joined(const std::vector<FlatStrip>& strips,
                                                   int neighbour, const FlatStrip& joined,
                                                   double min_width,
                                                   std::map<int, NarrowRaster>& rasters) {
  const FlatStrip& before = strips[neighbour];
  auto it = rasters.find(neighbour);
  if (it == rasters.end())
    it = rasters.emplace(neighbour, narrow_raster(before.vertices2d, before.triangles, min_width))
             .first;
  const NarrowRaster& raster = it->second;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t t = before.triangles.size(); t < joined.triangles.size(); ++t)
    for (int v : joined.triangles[t])
      lo = lo.cwiseMin(joined.vertices2d[v]), hi = hi.cwiseMax(joined.vertices2d[v]);
  if (!(lo.x() <= hi.x())) return {raster.fraction(), raster.fraction()};  // nothing taken
  lo -= Vec2::Constant(min_width), hi += Vec2::Constant(min_width);
  const NarrowRaster was =
      narrow_raster_in_box(before.vertices2d, before.triangles, min_width, lo, hi, raster);
  const NarrowRaster is =
      narrow_raster_in_box(joined.vertices2d, joined.triangles, min_width, lo, hi, raster);
  NarrowRaster result = raster;
  result.inside += is.inside - was.inside;
  result.narrow += is.narrow - was.narrow;
  return {raster.fraction(), result.fraction()};
}

}  // namespace papercraft::merge_detail
