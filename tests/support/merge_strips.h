#pragma once
// Test-only helpers of the merge tests: small flat strips built by hand (floors and the walls
// standing on them), strips unfolded from ruled strips, fixtures of real models' strips
// (tests/merge/data) and the checks every join must pass.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/strip.h"
#include "engine/unfold/sequential.h"
#include "nlohmann/json.hpp"
#include "support/flat_strips_json.h"
#include "support/unfold_checks.h"

namespace papercraft::merge_testing {

// The flat strips of `strip` unfolded, appended to `all` (ids and source strips their index).
inline void append(std::vector<FlatStrip>& all, const RuledStrip& strip) {
  auto flat = unfold_strip(strip, static_cast<int>(all.size()), static_cast<int>(all.size()));
  all.insert(all.end(), flat.begin(), flat.end());
}

// The triangles of all `strips`.
inline std::size_t triangle_count(const std::vector<FlatStrip>& strips) {
  std::size_t count = 0;
  for (const FlatStrip& s : strips) count += s.triangles.size();
  return count;
}

// The area of a strip laid flat with counter-clockwise triangles (expect_valid checks that).
inline double area_of(const FlatStrip& strip) {
  double sum = 0.0;
  for (const Triangle& t : strip.triangles) sum += unfold_testing::signed_area(strip, t);
  return sum;
}

// Every strip isometric and overlap-free, every boundary edge a labelled seam or open.
inline void expect_valid(const std::vector<FlatStrip>& strips) {
  for (const FlatStrip& s : strips) {
    unfold_testing::expect_isometric(s);
    EXPECT_EQ(unfold_testing::count_overlapping_pairs(s), 0) << "strip " << s.id;
    for (const BoundaryEdge& e : s.boundary) {
      EXPECT_TRUE(e.kind == EdgeKind::Seam || e.kind == EdgeKind::Open);
      EXPECT_EQ(e.kind == EdgeKind::Seam, !e.label.empty());
    }
  }
}

// Flat strips of a real model as the merge node had them, with the node's limits (model
// units): tests/merge/data, written from a run at 2% and 200 mm.
struct MergeFixture {
  double min_area = 0.0, min_width = 0.0;
  std::vector<FlatStrip> strips;
};

inline MergeFixture read_fixture(const std::string& name) {
  std::ifstream in(std::string(PAPERCRAFT_SOURCE_DIR) + "/tests/merge/data/" + name);
  EXPECT_TRUE(in) << "missing test data " << name;
  MergeFixture fixture;
  if (!in) return fixture;
  const nlohmann::json j = nlohmann::json::parse(in);
  fixture.min_area = j.at("min_area").get<double>();
  fixture.min_width = j.at("min_width").get<double>();
  fixture.strips = testing::read_flat_strips(j.at("strips"));
  return fixture;
}

// The strip of `strips` with id `id`, or null.
inline const FlatStrip* find_id(const std::vector<FlatStrip>& strips, int id) {
  for (const FlatStrip& s : strips)
    if (s.id == id) return &s;
  return nullptr;
}

// The floor a-b-c-d (at z = 0, corners counter-clockwise), laid out in the plane as it lies.
inline FlatStrip flat_floor(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  FlatStrip floor;
  floor.id = 0;
  floor.vertices3d = {a, b, c, d};
  for (const Vec3& p : floor.vertices3d) floor.vertices2d.emplace_back(p.x(), p.y());
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  return floor;
}

// A wall `h` high standing on the polyline `bottom` (at z = 0; points 0..n-1), its top
// points n..2n-1 `h` higher, unrolled straight along x. Walking `bottom` in order keeps the
// wall on the left, so it must run against the floor's edges.
inline FlatStrip straight_wall(const std::vector<Vec3>& bottom, double h) {
  FlatStrip wall;
  wall.id = 1;
  wall.source_strip = 1;
  const int n = static_cast<int>(bottom.size());
  double along = 0.0;
  for (int k = 0; k < n; ++k) {
    if (k > 0) along += (bottom[k] - bottom[k - 1]).norm();
    wall.vertices2d.push_back({along, 0.0});
    wall.vertices3d.push_back(bottom[k]);
  }
  for (int k = 0; k < n; ++k) {
    wall.vertices2d.push_back(wall.vertices2d[k] + Vec2(0, h));
    wall.vertices3d.push_back(bottom[k] + Vec3(0, 0, h));
  }
  for (int k = 0; k + 1 < n; ++k) {
    wall.triangles.push_back({k, k + 1, k + n + 1});
    wall.triangles.push_back({k, k + n + 1, k + n});
  }
  return wall;
}

// The 4 x 4 floor at z = 0 and a wall `h` high standing on two of its sides (c -> b -> a, a
// corner), unrolled straight.
inline FlatStrip corner_floor() {
  return flat_floor(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 4, 0), Vec3(0, 4, 0));
}

inline FlatStrip corner_wall(double h) {
  const Vec3 a(0, 0, 0), b(4, 0, 0), c(4, 4, 0), up(0, 0, h);
  FlatStrip wall;
  wall.id = 1;
  wall.source_strip = 1;
  wall.vertices3d = {c, b, a, c + up, b + up, a + up};
  wall.vertices2d = {{0, 0}, {4, 0}, {8, 0}, {0, h}, {4, h}, {8, h}};
  wall.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  return wall;
}

// A floor a -> b -> c -> d whose sides bend by 10 and 90 degrees (4, 4 and 3 long), and a
// wall 0.2 high standing on d -> c -> b -> a, unrolled straight.
inline std::pair<FlatStrip, FlatStrip> bent_floor_and_wall() {
  const double h = 0.2, turn = 10.0 * std::acos(-1.0) / 180.0;
  const Vec2 a(0, 0), b(4, 0), c = b + 4.0 * Vec2(std::cos(turn), std::sin(turn));
  const Vec2 d = c + 3.0 * Vec2(-std::sin(turn), std::cos(turn));
  auto lift = [](const Vec2& p, double z) { return Vec3(p.x(), p.y(), z); };
  FlatStrip floor;
  floor.id = 0;
  floor.vertices2d = {a, b, c, d};
  for (const Vec2& p : floor.vertices2d) floor.vertices3d.push_back(lift(p, 0));
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  const FlatStrip wall = straight_wall({lift(d, 0), lift(c, 0), lift(b, 0), lift(a, 0)}, h);
  return {floor, wall};
}

}  // namespace papercraft::merge_testing
