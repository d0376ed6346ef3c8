#include "core/piece_limits.h"

#include <gtest/gtest.h>

#include <cmath>

namespace papercraft {
namespace {

// A 100 x 40 plate in the plane z = 0 (rows of squares and one row 1.5 high at y = 20, two
// triangles each) with, where `tail` is given, a band 1.5 wide and `tail` long that leaves its
// right edge from that row and is bent down by 90 degrees: one connected piece, a sliver hung on
// a wide plate by its end.
Mesh plate_with_tail(double tail) {
  TriangleMesh mesh;
  const std::vector<double> ys = {0, 5, 10, 15, 20, 21.5, 25, 30, 35, 40};
  const int nx = 20, ny = static_cast<int>(ys.size()) - 1;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.vertices.push_back({5.0 * i, ys[j], 0.0});
  auto at = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  int a = at(nx, 4), b = at(nx, 5);  // the band's foot: (100, 20) to (100, 21.5)
  const int cells = static_cast<int>(std::round(tail / 5.0));
  for (int i = 1; i <= cells; ++i) {
    const int next_a = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back({100.0, 20.0, -5.0 * i});
    mesh.vertices.push_back({100.0, 21.5, -5.0 * i});
    mesh.triangles.push_back({b, a, next_a});
    mesh.triangles.push_back({b, next_a, next_a + 1});
    a = next_a, b = next_a + 1;
  }
  return to_mesh(mesh);
}

TEST(PieceLimits, ATailAlongAWidePieceFallsShortWhateverItsShare) {
  PieceLimits limits;
  limits.min_width = 3.0;
  limits.min_area = 100.0;
  // The plate: narrow only in its corners and beside the band's foot.
  EXPECT_TRUE(piece_fits(plate_with_tail(0.0), limits));
  // A 1.5 x 10 band: about 15 area units narrower than 0.6 min_width (1.8), under 8 times
  // 1.8^2 (26): a tip.
  EXPECT_TRUE(piece_fits(plate_with_tail(10.0), limits));
  // A 1.5 x 80 band: 120 area units, 3% of the piece, but one long sliver.
  const Mesh tailed = plate_with_tail(80.0);
  EXPECT_GT(piece_shortfall(tailed, limits), 0.0);
  // Without the bound on the region, only the share counts, and it is low.
  PieceLimits share_only = limits;
  share_only.max_sliver_area = 0.0;
  EXPECT_TRUE(piece_fits(tailed, share_only));
  // A longer tail falls further short.
  EXPECT_GT(piece_shortfall(plate_with_tail(100.0), limits), piece_shortfall(tailed, limits));
}

TEST(PieceLimits, SmallPieceFallsShortByTheAreaItLacks) {
  PieceLimits limits;
  limits.min_area = 8000.0;
  EXPECT_NEAR(piece_shortfall(plate_with_tail(0.0), limits), 0.5, 1e-9);  // 4,000 of 8,000
  EXPECT_TRUE(piece_fits(plate_with_tail(0.0), PieceLimits{}));
}

}  // namespace
}  // namespace papercraft
