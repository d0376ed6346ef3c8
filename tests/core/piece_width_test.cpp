#include "core/piece_width.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/errors.h"
#include "support/narrow_raster_reference.h"

namespace papercraft {
namespace {

// A w x h rectangle as two triangles.
void rectangle(double w, double h, std::vector<Vec2>& points, std::vector<Triangle>& triangles) {
  points = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  triangles = {{0, 1, 2}, {0, 2, 3}};
}

TEST(PieceWidth, WideRectangleIsNarrowOnlyInItsCorners) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  rectangle(100, 40, points, triangles);
  // The opening by a disc of diameter 3 misses only the four corners: 4 (r^2 - pi r^2 / 4).
  const double r = 1.5;
  const double corners = 4 * (r * r - M_PI * r * r / 4) / (100 * 40);
  EXPECT_NEAR(narrow_area_fraction(points, triangles, 3.0), corners, 2e-3);
}

TEST(PieceWidth, BandNarrowerThanTheDiscIsNarrowEverywhere) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  rectangle(150, 2.0, points, triangles);
  EXPECT_EQ(narrow_area_fraction(points, triangles, 3.0), 1.0);
  // ... and wide for a disc that fits.
  EXPECT_LT(narrow_area_fraction(points, triangles, 1.5), 0.02);
}

TEST(PieceWidth, DumbbellIsNarrowInItsHandleOnly) {
  // Two 20 x 20 squares joined by a 40 x 2 handle: the handle is narrow at 3, the squares not.
  const std::vector<Vec2> points = {{0, 0},  {20, 0},  {20, 20}, {0, 20},  {60, 0},   {80, 0},
                                    {80, 20}, {60, 20}, {20, 9},  {60, 9},  {60, 11}, {20, 11}};
  const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6},
                                           {4, 6, 7}, {8, 9, 10}, {8, 10, 11}};
  const double handle = 40.0 * 2.0 / (2 * 400 + 80);
  const double fraction = narrow_area_fraction(points, triangles, 3.0);
  EXPECT_GT(fraction, handle - 0.005);
  EXPECT_LT(fraction, handle + 0.02);
}

TEST(PieceWidth, LargestNarrowRegionIsOneSliverNotTheirSum) {
  // A 100 x 20 plate with two teeth above it: 1.5 x 30 (a sliver, 45 mm^2) and 1 x 20 (20 mm^2).
  // At 3 mm both teeth are narrow regions of their own, joined to the plate only where they
  // meet it; the largest region is the longer tooth (and the plate's corners beside it), not
  // the two together, however small a share of the piece either is.
  const std::vector<Vec2> points = {{0, 0},     {100, 0}, {100, 20}, {0, 20},  {20, 20}, {21.5, 20},
                                    {21.5, 50}, {20, 50}, {60, 20},  {61, 20}, {61, 40}, {60, 40}};
  const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3},  {4, 5, 6},
                                           {4, 6, 7}, {8, 9, 10}, {8, 10, 11}};
  const double largest = largest_narrow_region(points, triangles, 3.0);
  EXPECT_GT(largest, 40.0);
  EXPECT_LT(largest, 52.0);
  EXPECT_LT(narrow_area_fraction(points, triangles, 3.0), 0.04);
  // The raster it measured on the way is narrow_raster's.
  NarrowRaster raster;
  largest_narrow_region(points, triangles, 3.0, {}, &raster);
  const NarrowRaster direct = narrow_raster(points, triangles, 3.0);
  EXPECT_EQ(raster.inside, direct.inside);
  EXPECT_EQ(raster.narrow, direct.narrow);
  EXPECT_EQ(raster.cell, direct.cell);
  // The plate alone: only its corners, each a small region.
  const std::vector<Triangle> plate = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_LT(largest_narrow_region(points, plate, 3.0), 2.0);
  EXPECT_GT(largest_narrow_region(points, plate, 3.0), 0.0);
  // A band narrower than the disc everywhere: the whole band.
  std::vector<Vec2> band;
  std::vector<Triangle> band_triangles;
  rectangle(150, 2.0, band, band_triangles);
  EXPECT_NEAR(largest_narrow_region(band, band_triangles, 3.0), 300.0, 20.0);  // to a row of cells
}

// A 200 mm square has no sliver at any turn: its edges slanted to the raster used to leave a
// staircase of narrow cells one cell wide along the whole outline, joined at their corners into
// one region of 200 mm^2 and more between 30 and 60 degrees. A band 2 mm wide and 150 mm long
// stays one sliver of about 300 mm^2 at every turn.
TEST(PieceWidth, LargestNarrowRegionDoesNotDependOnTheTurn) {
  for (int step = 0; step <= 18; ++step) {
    const double angle = step * 3.14159265358979323846 / 36.0;
    SCOPED_TRACE(angle);
    const double c = std::cos(angle), s = std::sin(angle);
    const auto turned = [&](std::vector<Vec2> points) {
      for (Vec2& p : points) p = Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
      return points;
    };
    const std::vector<Vec2> square = turned({{0, 0}, {200, 0}, {200, 200}, {0, 200}});
    EXPECT_LT(largest_narrow_region(square, {{0, 1, 2}, {0, 2, 3}}, 3.0), 5.0);
    std::vector<Vec2> band;
    std::vector<Triangle> band_triangles;
    rectangle(150, 2.0, band, band_triangles);
    EXPECT_NEAR(largest_narrow_region(turned(band), band_triangles, 3.0), 300.0, 25.0);
  }
}

TEST(PieceWidth, NarrowMeasureIn3dFindsTheSliverAlongABentPiece) {
  // The plate with its two teeth of LargestNarrowRegionIsOneSliverNotTheirSum, the teeth folded
  // up by 60 degrees about the plate's edge: the same share and the same largest region (the
  // 1.5 x 30 tooth), measured in 3D.
  const std::vector<Vec2> flat = {{0, 0},     {100, 0}, {100, 20}, {0, 20},  {20, 20}, {21.5, 20},
                                  {21.5, 50}, {20, 50}, {60, 20},  {61, 20}, {61, 40}, {60, 40}};
  TriangleMesh piece;
  for (const Vec2& p : flat) {
    const double up = std::max(0.0, p.y() - 20.0);
    piece.vertices.push_back(
        {p.x(), std::min(p.y(), 20.0) + up * std::cos(M_PI / 3), up * std::sin(M_PI / 3)});
  }
  piece.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}, {8, 9, 10}, {8, 10, 11}};
  const NarrowMeasure measure = narrow_measure(piece, 3.0);
  EXPECT_EQ(measure.fraction, narrow_area_fraction(piece, 3.0));
  EXPECT_NEAR(measure.fraction, narrow_area_fraction(flat, piece.triangles, 3.0), 0.01);
  EXPECT_GT(measure.largest_region, 40.0);
  EXPECT_LT(measure.largest_region, 52.0);
  // The plate alone: its corners; a tip, not a sliver.
  TriangleMesh plate = piece;
  plate.triangles.resize(2);
  EXPECT_GT(narrow_measure(plate, 3.0).largest_region, 0.0);
  EXPECT_LT(narrow_measure(plate, 3.0).largest_region, 2.0);
  // A band narrower than the disc, bent into a half cylinder of radius 20 along its length:
  // one region, the whole band.
  TriangleMesh band;
  const int steps = 40;
  for (int i = 0; i <= steps; ++i) {
    const double angle = M_PI * i / steps;
    band.vertices.push_back({20 * std::cos(angle), 20 * std::sin(angle), 0.0});
    band.vertices.push_back({20 * std::cos(angle), 20 * std::sin(angle), 2.0});
  }
  for (int i = 0; i < steps; ++i)
    band.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3}),
        band.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  double area = 0.0;
  for (const Triangle& t : band.triangles)
    area += 0.5 * (band.vertices[t[1]] - band.vertices[t[0]])
                      .cross(band.vertices[t[2]] - band.vertices[t[0]])
                      .norm();
  const NarrowMeasure whole = narrow_measure(band, 3.0);
  EXPECT_EQ(whole.fraction, 1.0);
  EXPECT_NEAR(whole.largest_region, area, 1e-9 * area);
  // Cut in two halves apart from each other (the middle rungs left out): two regions of half.
  TriangleMesh halves = band;
  halves.triangles.erase(halves.triangles.begin() + steps - 4,
                         halves.triangles.begin() + steps + 4);
  EXPECT_LT(narrow_measure(halves, 3.0).largest_region, 0.51 * area);
  // A closed piece has no boundary, so nothing narrow.
  EXPECT_EQ(narrow_measure(TriangleMesh{}, 3.0).largest_region, 0.0);
  EXPECT_THROW(narrow_measure(piece, -1.0), InvalidInputException);
}

TEST(PieceWidth, NeedleTrianglesMeasureLikeTheirShapeWithSamplesForTheirArea) {
  // A 100 x 20 plate with a 1.5 x 30 tooth on its top edge, bent up by 60 degrees, meshed twice:
  // once in near-square cells, once in needles (the plate in triangles 20 long and 0.25 wide,
  // as a CAD mesh has them). Both measure the same, and the needles take about as many samples
  // as the squares do, not k x k each with k set by their 20-long side.
  auto mesh = [](double dx, double dy) {
    TriangleMesh piece;
    auto grid = [&](double x0, double w, double h, double cell_x, double cell_y, bool bent) {
      const int nx = static_cast<int>(std::lround(w / cell_x)),
                ny = static_cast<int>(std::lround(h / cell_y));
      const int first = static_cast<int>(piece.vertices.size());
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
          const double x = x0 + w * i / nx, y = h * j / ny;
          piece.vertices.push_back(
              bent ? Vec3{x, 20.0 + y * std::cos(M_PI / 3), y * std::sin(M_PI / 3)}
                   : Vec3{x, y, 0.0});
        }
      auto at = [&](int i, int j) { return first + j * (nx + 1) + i; };
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          piece.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          piece.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    };
    grid(0.0, 100.0, 20.0, dx, dy, false);
    grid(20.0, 1.5, 30.0, 1.5, 30.0, true);  // the tooth: two triangles 30 long, 1.5 wide
    return piece;
  };
  const TriangleMesh squares = mesh(1.0, 1.0), needles = mesh(0.25, 20.0);
  const NarrowMeasure square = narrow_measure(squares, 3.0), needle = narrow_measure(needles, 3.0);
  EXPECT_NEAR(needle.fraction, square.fraction, 0.005);
  EXPECT_NEAR(needle.largest_region, square.largest_region, 0.05 * square.largest_region);
  EXPECT_GT(square.largest_region, 40.0);  // the tooth
  EXPECT_LT(square.largest_region, 52.0);
  // The spacing is 3 / 8: each square's two triangles take 4 x 4 samples, 64,000 in all.
  EXPECT_LT(square.samples, 80'000u);
  EXPECT_LT(needle.samples, square.samples);  // k x k per needle: 800 x 54^2 = 2.3 million
}

TEST(PieceWidth, OrientationAndOverlapDoNotMatter) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  rectangle(10, 10, points, triangles);
  const double ccw = narrow_area_fraction(points, triangles, 4.0);
  triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 2}};
  EXPECT_NEAR(narrow_area_fraction(points, triangles, 4.0), ccw, 1e-12);
}

// A 200 x 100 rectangle and, when `tab`, a band 40 long and 2 wide (narrow at 3) on its right
// side, leaving it at 30 degrees: across the raster's rows, so that how the raster cuts its
// outline evens out along it.
const Vec2 kTabLength = 40.0 * Vec2(std::cos(M_PI / 6), std::sin(M_PI / 6));
const double kTabBase = 2.0 / std::cos(M_PI / 6);

void plate(bool tab, std::vector<Vec2>& points, std::vector<Triangle>& triangles) {
  rectangle(200, 100, points, triangles);
  if (!tab) return;
  const Vec2 a(200, 50), b(200, 50 + kTabBase);
  points.insert(points.end(), {a, a + kTabLength, b + kTabLength, b});
  triangles.insert(triangles.end(), {{4, 5, 6}, {4, 6, 7}});
}

TEST(PieceWidth, RasterInABoxOverThePieceIsItsRaster) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  plate(true, points, triangles);
  const NarrowRaster whole = narrow_raster(points, triangles, 3.0);
  EXPECT_EQ(whole.fraction(), narrow_area_fraction(points, triangles, 3.0));
  EXPECT_GT(whole.narrow * whole.cell * whole.cell, 70.0);  // the band, and the corners
  const NarrowRaster all =
      narrow_raster_in_box(points, triangles, 3.0, {-1, -1}, {241, 122}, whole);
  EXPECT_EQ(all.inside, whole.inside);
  EXPECT_EQ(all.narrow, whole.narrow);
  // Nothing narrow in the middle of the plate, nothing at all away from it.
  const NarrowRaster middle =
      narrow_raster_in_box(points, triangles, 3.0, {50, 20}, {150, 80}, whole);
  EXPECT_GT(middle.inside, 0);
  EXPECT_EQ(middle.narrow, 0);
  EXPECT_EQ(narrow_raster_in_box(points, triangles, 3.0, {300, 300}, {310, 310}, whole).inside, 0);
}

TEST(PieceWidth, RasterInABoxSeesThePieceAroundTheBox) {
  // A 4 mm band is wide at 3; a box over its lower millimetre alone holds no disc of 3, but
  // whether it is narrow depends on where the band's other edge lies, outside the box.
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  rectangle(100, 4, points, triangles);
  NarrowRaster grid = narrow_raster(points, triangles, 3.0);
  NarrowRaster box = narrow_raster_in_box(points, triangles, 3.0, {10, 0}, {90, 1}, grid);
  EXPECT_GT(box.inside * grid.cell * grid.cell, 70.0);
  EXPECT_EQ(box.narrow, 0);
  // A 2 mm band is narrow there: all of the box's 80 mm^2, to a row of cells.
  rectangle(100, 2, points, triangles);
  grid = narrow_raster(points, triangles, 3.0);
  box = narrow_raster_in_box(points, triangles, 3.0, {10, 0}, {90, 1}, grid);
  EXPECT_GT(box.narrow * grid.cell * grid.cell, 70.0);
  EXPECT_EQ(box.narrow, box.inside);
}

TEST(PieceWidth, RasterInABoxAroundAnEditGivesTheRasterOfTheWhole) {
  // The plate gets the band: its raster changes only within one width of the band, so the box
  // there (the band +- 3) turns the plate's raster into the plated band's on the same grid,
  // cell for cell, though the plate is far larger than the box.
  std::vector<Vec2> before_points, after_points;
  std::vector<Triangle> before, after;
  plate(false, before_points, before);
  plate(true, after_points, after);
  const double width = 3.0;
  const Vec2 lo(200 - width, 50 - width),
      hi = Vec2(200, 50 + kTabBase) + kTabLength + Vec2::Constant(width);
  const NarrowRaster grid = narrow_raster(before_points, before, width);
  const NarrowRaster was = narrow_raster_in_box(before_points, before, width, lo, hi, grid);
  const NarrowRaster is = narrow_raster_in_box(after_points, after, width, lo, hi, grid);
  // The whole of the plated band on the plate's grid.
  const NarrowRaster whole =
      narrow_raster_in_box(after_points, after, width, {-10, -10}, {250, 130}, grid);
  EXPECT_EQ(grid.inside - was.inside + is.inside, whole.inside);
  EXPECT_EQ(grid.narrow - was.narrow + is.narrow, whole.narrow);
  EXPECT_GT((is.narrow - was.narrow) * grid.cell * grid.cell, 70.0);  // the band, 80 mm^2
  // ... and, on its own grid, the same share to how the rasters cut the outline.
  EXPECT_NEAR(whole.fraction(), narrow_area_fraction(after_points, after, width), 1e-4);
}

TEST(PieceWidth, RasterCountsMatchBruteForce) {
  // Random soups of a few triangles (bands, fans, overlaps, both orientations) and widths,
  // on the default raster and on one coarsened by max_cells (a disc of 1 to 3 cells).
  std::mt19937 random(12);
  std::uniform_real_distribution<double> coordinate(0.0, 30.0), unit(0.0, 1.0);
  int narrow_seen = 0, wide_seen = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Vec2> points;
    std::vector<Triangle> triangles;
    const int count = 1 + trial % 5;
    for (int t = 0; t < count; ++t) {
      for (int k = 0; k < 3; ++k) points.emplace_back(coordinate(random), coordinate(random));
      triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    const double width = 1.0 + 7.0 * unit(random);
    PieceWidthOptions options;
    if (trial % 3 == 2) options.max_cells = 2'000;
    const NarrowRaster raster = narrow_raster(points, triangles, width, options);
    const NarrowRaster expected =
        testing::brute_force_narrow_raster(points, triangles, width, raster);
    ASSERT_GT(expected.inside, 0) << "trial " << trial;
    EXPECT_EQ(raster.inside, expected.inside) << "trial " << trial;
    EXPECT_EQ(raster.narrow, expected.narrow) << "trial " << trial;
    // ... and by distance transforms, as the bench's reference times it.
    const NarrowRaster transformed = testing::distance_transform_narrow_raster(
        testing::inside_cells(points, triangles, raster, static_cast<int>(width / raster.cell) + 2),
        width, raster);
    EXPECT_EQ(transformed.inside, expected.inside) << "trial " << trial;
    EXPECT_EQ(transformed.narrow, expected.narrow) << "trial " << trial;
    narrow_seen += raster.narrow > 0;
    wide_seen += raster.narrow < raster.inside;
  }
  // The trials hold pieces narrow in parts and wide in parts, not only one kind.
  EXPECT_GT(narrow_seen, 20);
  EXPECT_GT(wide_seen, 20);
}

TEST(PieceWidth, BadInputThrows) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  rectangle(1, 1, points, triangles);
  EXPECT_THROW(narrow_area_fraction(points, triangles, 0.0), InvalidInputException);
  EXPECT_THROW(narrow_area_fraction(points, triangles, NAN), InvalidInputException);
  triangles.push_back({0, 1, 7});
  EXPECT_THROW(narrow_area_fraction(points, triangles, 1.0), InvalidInputException);
  EXPECT_EQ(narrow_area_fraction(points, {}, 1.0), 0.0);
  const NarrowRaster grid = narrow_raster(points, {{0, 1, 2}}, 1.0);
  EXPECT_THROW(narrow_raster_in_box(points, triangles, 1.0, {0, 0}, {1, 1}, grid),
               InvalidInputException);
  triangles.pop_back();
  EXPECT_THROW(narrow_raster_in_box(points, triangles, 1.0, {1, 0}, {0, 1}, grid),
               InvalidInputException);
  EXPECT_THROW(narrow_raster_in_box(points, triangles, 1.0, {0, 0}, {NAN, 1}, grid),
               InvalidInputException);
  EXPECT_THROW(narrow_raster_in_box(points, triangles, 0.0, {0, 0}, {1, 1}, grid),
               InvalidInputException);
  EXPECT_THROW(narrow_raster_in_box(points, triangles, 1.0, {0, 0}, {1, 1}, NarrowRaster{}),
               InvalidInputException);
}

}  // namespace
}  // namespace papercraft
