#include "core/piece_width.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"

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

TEST(PieceWidth, OrientationAndOverlapDoNotMatter) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  rectangle(10, 10, points, triangles);
  const double ccw = narrow_area_fraction(points, triangles, 4.0);
  triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 2}};
  EXPECT_NEAR(narrow_area_fraction(points, triangles, 4.0), ccw, 1e-12);
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
}

}  // namespace
}  // namespace papercraft
