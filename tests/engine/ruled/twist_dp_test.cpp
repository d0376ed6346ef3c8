#include "engine/ruled/twist_dp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/mesh.h"

namespace papercraft {
namespace {

constexpr double kPi = 3.14159265358979323846;

Polyline circle(int count, double radius, double z, double phase = 0.0, bool clockwise = false) {
  Polyline p;
  p.closed = true;
  for (int k = 0; k < count; ++k) {
    const double t = (clockwise ? -1.0 : 1.0) * (phase + 2.0 * kPi * k / count);
    p.points.emplace_back(radius * std::cos(t), radius * std::sin(t), z);
  }
  return p;
}

Polyline square(double z) {
  Polyline p;
  p.closed = true;
  p.points = {Vec3(0, 0, z), Vec3(1, 0, z), Vec3(1, 1, z), Vec3(0, 1, z)};
  return p;
}

Polyline reversed(Polyline p) {
  std::reverse(p.points.begin(), p.points.end());
  std::reverse(p.uvs.begin(), p.uvs.end());
  return p;
}

// A wobbly closed curve around the z axis at height z, or an open one along x.
Polyline random_polyline(std::mt19937& rng, int count, double z, bool closed) {
  std::uniform_real_distribution<double> noise(-0.3, 0.3);
  Polyline p;
  p.closed = closed;
  for (int k = 0; k < count; ++k) {
    if (closed) {
      const double t = 2.0 * kPi * (k + 0.4 * noise(rng)) / count;
      const double r = 1.0 + noise(rng);
      p.points.emplace_back(r * std::cos(t), r * std::sin(t), z + noise(rng));
    } else {
      p.points.emplace_back(static_cast<double>(k) / count + 0.2 * noise(rng), noise(rng),
                            z + noise(rng));
    }
  }
  return p;
}

// Independent twist cost of the paper: tangents by central differences in the traversal
// direction, 1 where a normal is undefined.
Vec3 tangent(const std::vector<Vec3>& p, bool closed, int i) {
  const int n = static_cast<int>(p.size());
  const int prev = closed ? (i + n - 1) % n : std::max(i - 1, 0);
  const int next = closed ? (i + 1) % n : std::min(i + 1, n - 1);
  return p[next] - p[prev];
}

double twist(const Vec3& a, const Vec3& da, const Vec3& b, const Vec3& db) {
  const Vec3 na = (a - b).cross(da);
  const Vec3 nb = (a - b).cross(db);
  if (na.norm() < 1e-12 * (a - b).norm() * da.norm() ||
      nb.norm() < 1e-12 * (a - b).norm() * db.norm() || na.norm() == 0.0 || nb.norm() == 0.0) {
    return 1.0;
  }
  return 1.0 - na.normalized().dot(nb.normalized());
}

double twist_cell(const Polyline& a, const std::vector<Vec3>& b_points, bool closed, int i, int j) {
  return twist(a.points[i], tangent(a.points, closed, i), b_points[j],
               tangent(b_points, closed, j));
}

// O(n m^2): every start b_s for a_0 separately, both directions of B, DP over paths with
// their numbers of horizontal and vertical runs (capped at 2). A path with a single run of
// either kind is a double fan (a full row or column: a ruling used twice); those are excluded
// unless `allow_double_fans`.
double brute_force_cyclic_twist(const Polyline& a, const Polyline& b,
                                bool allow_double_fans = false) {
  const int n = static_cast<int>(a.points.size());
  const int m = static_cast<int>(b.points.size());
  const double inf = std::numeric_limits<double>::infinity();
  double best = inf;
  for (bool reverse : {false, true}) {
    std::vector<Vec3> bp = b.points;
    if (reverse) std::reverse(bp.begin(), bp.end());
    for (int s = 0; s < m; ++s) {
      // d[i][k][last step: 0 horizontal, 1 vertical, 2 none][horizontal runs][vertical runs]
      using State = std::array<std::array<std::array<double, 3>, 3>, 3>;
      State empty;
      for (auto& x : empty) {
        for (auto& y : x) y.fill(inf);
      }
      std::vector<std::vector<State>> d(n + 1, std::vector<State>(m + 1, empty));
      for (int i = 0; i <= n; ++i) {
        for (int k = 0; k <= m; ++k) {
          const double c = twist_cell(a, bp, true, i % n, (s + k) % m);
          if (i == 0 && k == 0) {
            d[0][0][2][0][0] = c;
            continue;
          }
          for (int last = 0; last < 3; ++last) {
            for (int h = 0; h < 3; ++h) {
              for (int v = 0; v < 3; ++v) {
                if (k > 0 && std::isfinite(d[i][k - 1][last][h][v])) {
                  const int h2 = last == 0 ? h : std::min(h + 1, 2);
                  double& to = d[i][k][0][h2][v];
                  to = std::min(to, d[i][k - 1][last][h][v] + c);
                }
                if (i > 0 && std::isfinite(d[i - 1][k][last][h][v])) {
                  const int v2 = last == 1 ? v : std::min(v + 1, 2);
                  double& to = d[i][k][1][h][v2];
                  to = std::min(to, d[i - 1][k][last][h][v] + c);
                }
              }
            }
          }
        }
      }
      double end = inf;
      for (int last = 0; last < 2; ++last) {
        for (int h = 1; h < 3; ++h) {
          for (int v = 1; v < 3; ++v) {
            if (allow_double_fans || (h == 2 && v == 2)) end = std::min(end, d[n][m][last][h][v]);
          }
        }
      }
      best = std::min(best, end - twist_cell(a, bp, true, 0, s));
    }
  }
  return best;
}

using Edge = std::pair<int, int>;

std::map<Edge, int> directed_edges(const RuledStrip& strip) {
  std::map<Edge, int> edges;
  for (const Triangle& t : strip.mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  return edges;
}

// Rulings as (A index, B index within B).
std::set<Edge> rulings(const RuledStrip& strip) {
  std::set<Edge> out;
  for (const auto& [edge, count] : directed_edges(strip)) {
    const auto [u, v] = edge;
    if (u < strip.a_count && v >= strip.a_count) out.insert({u, v - strip.a_count});
    if (v < strip.a_count && u >= strip.a_count) out.insert({v, u - strip.a_count});
  }
  return out;
}

// True when B's edges appear as (b_{j+1}, b_j) in the triangles, i.e. B was matched backwards.
bool b_matched_backwards(const RuledStrip& strip) {
  const auto edges = directed_edges(strip);
  const int base = strip.a_count;
  for (int j = 0; j + 1 < strip.b_count; ++j) {
    if (edges.count({base + j + 1, base + j})) return true;
    if (edges.count({base + j, base + j + 1})) return false;
  }
  ADD_FAILURE() << "no B edge in the strip";
  return false;
}

double recomputed_twist(const RuledStrip& strip, const Polyline& a, const Polyline& b) {
  const bool backwards = b_matched_backwards(strip);
  std::vector<Vec3> bp = b.points;
  if (backwards) std::reverse(bp.begin(), bp.end());
  const int m = strip.b_count;
  double sum = 0.0;
  for (const auto& [i, j] : rulings(strip)) {
    sum += twist_cell(a, bp, a.closed, i, backwards ? m - 1 - j : j);
  }
  return sum;
}

double triangle_area(const RuledStrip& strip, const Triangle& t) {
  const auto& v = strip.mesh.vertices;
  return 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm();
}

// Consistent orientation: no directed edge twice, every A edge as (a_{i+1}, a_i), every B edge
// in one direction, every triangle with vertices on both polylines.
void expect_oriented_strip(const RuledStrip& strip) {
  const auto edges = directed_edges(strip);
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << "directed edge " << edge.first << "->" << edge.second;
  }
  const int n = strip.a_count;
  const int a_edges = strip.a_closed ? n : n - 1;
  for (int i = 0; i < a_edges; ++i) {
    EXPECT_EQ(edges.count({(i + 1) % n, i}), 1u) << "A edge " << i;
  }
  const int m = strip.b_count;
  const int b_edges = strip.b_closed ? m : m - 1;
  int forward = 0;
  int backward = 0;
  for (int j = 0; j < b_edges; ++j) {
    forward += edges.count({n + j, n + (j + 1) % m});
    backward += edges.count({n + (j + 1) % m, n + j});
  }
  EXPECT_TRUE((forward == b_edges && backward == 0) || (backward == b_edges && forward == 0))
      << forward << " forward and " << backward << " backward B edges";
  for (const Triangle& t : strip.mesh.triangles) {
    const int on_a = (t[0] < n) + (t[1] < n) + (t[2] < n);
    EXPECT_TRUE(on_a == 1 || on_a == 2);
  }
}

TEST(TwistDp, SquaresAtDifferentHeightsGetVerticalCornerRulings) {
  for (bool b_backwards : {false, true}) {
    const Polyline a = square(0.0);
    const Polyline b = b_backwards ? reversed(square(1.0)) : square(1.0);
    const RuledStrip strip = twist_minimizing_strip(a, b);
    ASSERT_EQ(strip.mesh.triangles.size(), 8u);
    ASSERT_EQ(strip.mesh.vertices.size(), 8u);
    EXPECT_EQ(strip.mesh.vertices[4 + 1], b.points[1]);  // B keeps its own order
    expect_oriented_strip(strip);
    EXPECT_EQ(b_matched_backwards(strip), b_backwards);
    const auto r = rulings(strip);
    EXPECT_EQ(r.size(), 8u);
    for (int i = 0; i < 4; ++i) {
      const int j = b_backwards ? 3 - i : i;
      EXPECT_TRUE(r.count({i, j})) << "vertical ruling at corner " << i;
      EXPECT_NEAR((strip.mesh.vertices[i] - strip.mesh.vertices[4 + j]).norm(), 1.0, 1e-15);
    }
    for (const Triangle& t : strip.mesh.triangles) EXPECT_NEAR(triangle_area(strip, t), 0.5, 1e-12);
    EXPECT_NEAR(strip.twist_cost, recomputed_twist(strip, a, b), 1e-12);
  }
}

TEST(TwistDp, CylinderBetweenIdenticalCirclesIsNearlyDevelopable) {
  for (int count : {16, 64}) {
    const Polyline a = circle(count, 1.0, 0.0);
    const Polyline b = circle(count, 1.0, 2.0, 0.0, /*clockwise=*/true);  // as a part's loop
    const RuledStrip strip = twist_minimizing_strip(a, b);
    ASSERT_EQ(static_cast<int>(strip.mesh.triangles.size()), 2 * count);
    expect_oriented_strip(strip);
    const auto r = rulings(strip);
    int vertical = 0;
    for (const auto& [i, j] : r) {
      const Vec3 d = strip.mesh.vertices[i] - strip.mesh.vertices[count + j];
      if (std::hypot(d.x(), d.y()) < 1e-12) ++vertical;
      // Every other ruling is a diagonal of one quad of the cylinder.
      EXPECT_LT(std::hypot(d.x(), d.y()), 2.0 * std::sin(kPi / count) + 1e-12);
    }
    EXPECT_EQ(vertical, count);
    // A diagonal's twist is about (2 pi / count)^2 / 2: the total vanishes as 1 / count.
    EXPECT_LT(strip.twist_cost, 1.1 * 2.0 * kPi * kPi / count);
    EXPECT_NEAR(strip.twist_cost, recomputed_twist(strip, a, b), 1e-12);
  }
}

TEST(TwistDp, CylinderStripNormalsAgreeWithThePart) {
  // A grid cylinder part: its two boundary loops (mesh on the right) give A and B.
  const int around = 12;
  const int rings = 4;
  TriangleMesh grid;
  for (int r = 0; r < rings; ++r) {
    for (int k = 0; k < around; ++k) {
      const double t = 2.0 * kPi * k / around;
      grid.vertices.emplace_back(std::cos(t), std::sin(t), 0.5 * r);
    }
  }
  for (int r = 0; r + 1 < rings; ++r) {
    for (int k = 0; k < around; ++k) {
      const int v00 = r * around + k;
      const int v01 = r * around + (k + 1) % around;
      const int v10 = v00 + around;
      const int v11 = v01 + around;
      grid.triangles.push_back({v00, v01, v11});  // counter-clockwise seen from outside
      grid.triangles.push_back({v00, v11, v10});
    }
  }
  const Mesh part = to_mesh(grid);
  const auto loops = boundary_loops(part);
  ASSERT_EQ(loops.size(), 2u);
  Polyline a;
  Polyline b;
  a.closed = b.closed = true;
  for (int v : loops[0]) a.points.push_back(grid.vertices[v]);
  for (int v : loops[1]) b.points.push_back(grid.vertices[v]);
  for (const auto& [first, second] : {std::pair{a, b}, std::pair{b, a}}) {
    const RuledStrip strip = twist_minimizing_strip(first, second);
    expect_oriented_strip(strip);
    for (const Triangle& t : strip.mesh.triangles) {
      const auto& v = strip.mesh.vertices;
      const Vec3 normal = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
      Vec3 outward = (v[t[0]] + v[t[1]] + v[t[2]]) / 3.0;
      outward.z() = 0.0;
      EXPECT_GT(normal.dot(outward), 0.0);
    }
  }
}

TEST(TwistDp, OpenArcsMatchTheirCommonVerticesVertically) {
  // B samples the same arc twice as densely, every other point above one of A's.
  Polyline a;
  Polyline b;
  const int count = 7;
  for (int k = 0; k < count; ++k) {
    const double t = 0.15 * k;
    a.points.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  for (int k = 0; k < 2 * count - 1; ++k) {
    const double t = 0.075 * k;
    b.points.emplace_back(std::cos(t), std::sin(t), 1.0);
  }
  TwistOptions options;
  options.ruling_length_weight = 0.0;
  const RuledStrip strip = twist_minimizing_strip(a, b, options);
  ASSERT_EQ(static_cast<int>(strip.mesh.triangles.size()), count + 2 * count - 1 - 2);
  expect_oriented_strip(strip);
  const auto r = rulings(strip);
  EXPECT_EQ(static_cast<int>(r.size()), count + 2 * count - 1 - 1);
  for (int i = 0; i < count; ++i) EXPECT_TRUE(r.count({i, 2 * i})) << "ruling " << i;
  EXPECT_NEAR(strip.twist_cost, recomputed_twist(strip, a, b), 1e-12);
}

TEST(TwistDp, PlanarTieIsBrokenByShortRulings) {
  // Two parallel segments in a plane: every correspondence has zero twist.
  Polyline a;
  Polyline b;
  for (int k = 0; k < 5; ++k) {
    a.points.emplace_back(k, 0.0, 0.0);
    b.points.emplace_back(k, 1.0, 0.0);
  }
  const RuledStrip strip = twist_minimizing_strip(a, b);
  ASSERT_EQ(strip.mesh.triangles.size(), 8u);
  expect_oriented_strip(strip);
  const auto r = rulings(strip);
  for (int k = 0; k < 5; ++k) EXPECT_TRUE(r.count({k, k})) << "ruling " << k;
  EXPECT_NEAR(strip.twist_cost, 0.0, 1e-12);
}

TEST(TwistDp, CyclicOptimumEqualsBruteForceOverAllStarts) {
  std::mt19937 rng(1234);
  const std::vector<std::pair<int, int>> sizes = {{3, 3},  {4, 7},  {7, 5},   {9, 9},
                                                  {5, 17}, {20, 9}, {13, 16}, {24, 24}};
  TwistOptions exact;
  exact.ruling_length_weight = 0.0;
  for (const auto& [n, m] : sizes) {
    for (int trial = 0; trial < 3; ++trial) {
      const Polyline a = random_polyline(rng, n, 0.0, true);
      Polyline b = random_polyline(rng, m, 1.0, true);
      // Any vertex of B may be the one matched to a_0.
      std::rotate(b.points.begin(), b.points.begin() + rng() % m, b.points.end());
      if (trial == 1) b = reversed(b);
      const double expected = brute_force_cyclic_twist(a, b);
      const RuledStrip strip = twist_minimizing_strip(a, b, exact);
      ASSERT_EQ(static_cast<int>(strip.mesh.triangles.size()), n + m);
      EXPECT_NEAR(strip.twist_cost, expected, 1e-9) << n << "x" << m << " trial " << trial;
      EXPECT_NEAR(strip.twist_cost, recomputed_twist(strip, a, b), 1e-9);
      expect_oriented_strip(strip);
      for (const Triangle& t : strip.mesh.triangles) EXPECT_GT(triangle_area(strip, t), 1e-6);

      // The tie-breaking length term costs at most its weight per ruling.
      const RuledStrip tied = twist_minimizing_strip(a, b);
      const double weight = TwistOptions{}.ruling_length_weight;
      EXPECT_GE(tied.twist_cost, expected - 1e-9);
      EXPECT_LE(tied.twist_cost, expected + weight * (n + m) + 1e-9);
    }
  }
}

TEST(TwistDp, DoubleFanOptimaAreReplacedByTheBestManifoldStrip) {
  // Tiny random loops whose unrestricted optimum is a double fan (one ruling used twice).
  std::mt19937 rng(7);
  TwistOptions exact;
  exact.ruling_length_weight = 0.0;
  TwistOptions divide_and_conquer = exact;
  divide_and_conquer.max_each_start_work = 0;
  int double_fan_cases = 0;
  for (int trial = 0; trial < 400 && double_fan_cases < 12; ++trial) {
    const int n = 3 + trial % 3;
    const int m = 3 + (trial / 3) % 3;
    const Polyline a = random_polyline(rng, n, 0.0, true);
    const Polyline b = random_polyline(rng, m, 0.2, true);
    const double manifold = brute_force_cyclic_twist(a, b);
    if (!(brute_force_cyclic_twist(a, b, true) < manifold - 1e-9)) continue;
    ++double_fan_cases;
    for (const TwistOptions& options : {exact, divide_and_conquer}) {
      const RuledStrip strip = twist_minimizing_strip(a, b, options);
      expect_oriented_strip(strip);
      EXPECT_EQ(static_cast<int>(rulings(strip).size()), n + m);
      EXPECT_NEAR(strip.twist_cost, recomputed_twist(strip, a, b), 1e-9);
      if (options.max_each_start_work > 0) {
        EXPECT_NEAR(strip.twist_cost, manifold, 1e-9);
      }
    }
  }
  EXPECT_GE(double_fan_cases, 3);
}

TEST(TwistDp, WithoutReversalOnlyTheGivenDirectionIsUsed) {
  const Polyline a = circle(10, 1.0, 0.0);
  const Polyline b = circle(10, 1.0, 1.0, 0.0, /*clockwise=*/true);
  TwistOptions options;
  options.try_reversed_b = false;
  const RuledStrip forced = twist_minimizing_strip(a, b, options);
  EXPECT_FALSE(b_matched_backwards(forced));
  const RuledStrip free = twist_minimizing_strip(a, b);
  EXPECT_TRUE(b_matched_backwards(free));
  EXPECT_LT(free.twist_cost, forced.twist_cost);
}

TEST(TwistDp, BDirectionForcesOneTraversalWhateverItCosts) {
  const Polyline a = circle(10, 1.0, 0.0);
  const Polyline b = circle(10, 1.0, 1.0, 0.0, /*clockwise=*/true);
  TwistOptions options;
  options.b_direction = 1;  // as given, though backwards twists less
  const RuledStrip given = twist_minimizing_strip(a, b, options);
  EXPECT_FALSE(b_matched_backwards(given));
  options.b_direction = -1;
  const RuledStrip backwards = twist_minimizing_strip(a, b, options);
  EXPECT_TRUE(b_matched_backwards(backwards));
  EXPECT_LT(backwards.twist_cost, given.twist_cost);
  // Backwards forced on a B given the cheap way round: the dearer strip.
  const Polyline b_ccw = circle(10, 1.0, 1.0);
  EXPECT_TRUE(b_matched_backwards(twist_minimizing_strip(a, b_ccw, options)));
  EXPECT_GT(twist_minimizing_strip(a, b_ccw, options).twist_cost,
            twist_minimizing_strip(a, b_ccw).twist_cost);
}

TEST(TwistDp, OpenOpenTriangleCountAndOrientation) {
  std::mt19937 rng(99);
  for (const auto& [n, m] : std::vector<std::pair<int, int>>{{2, 2}, {2, 6}, {8, 3}, {15, 15}}) {
    const Polyline a = random_polyline(rng, n, 0.0, false);
    const Polyline b = random_polyline(rng, m, 1.0, false);
    const RuledStrip strip = twist_minimizing_strip(a, b);
    EXPECT_EQ(static_cast<int>(strip.mesh.triangles.size()), n + m - 2);
    EXPECT_FALSE(strip.a_closed);
    EXPECT_FALSE(strip.b_closed);
    expect_oriented_strip(strip);
    EXPECT_FALSE(b_matched_backwards(strip));
    const auto r = rulings(strip);
    EXPECT_TRUE(r.count({0, 0}));
    EXPECT_TRUE(r.count({n - 1, m - 1}));
    EXPECT_EQ(static_cast<int>(r.size()), n + m - 1);
    EXPECT_NEAR(strip.twist_cost, recomputed_twist(strip, a, b), 1e-9);
    for (const Triangle& t : strip.mesh.triangles) EXPECT_GT(triangle_area(strip, t), 1e-9);
  }
}

TEST(TwistDp, PointAgainstPolylineIsAFan) {
  Polyline apex;
  apex.points = {Vec3(0, 0, 2)};
  const Polyline ring = circle(9, 1.0, 0.0);
  Polyline open_ring = ring;
  open_ring.closed = false;

  const RuledStrip cone = twist_minimizing_strip(ring, apex);
  EXPECT_EQ(cone.mesh.triangles.size(), 9u);
  EXPECT_EQ(cone.b_count, 1);
  EXPECT_EQ(cone.twist_cost, 0.0);
  expect_oriented_strip(cone);
  for (const Triangle& t : cone.mesh.triangles) {
    EXPECT_TRUE(t[0] == 9 || t[1] == 9 || t[2] == 9);
    // A's edges as (a_{i+1}, a_i): a counter-clockwise ring is the boundary loop of the
    // inward-facing cone, so the normals point down.
    const auto& v = cone.mesh.vertices;
    EXPECT_LT((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).z(), 0.0);
  }

  const RuledStrip apex_first = twist_minimizing_strip(apex, ring);
  EXPECT_EQ(apex_first.mesh.triangles.size(), 9u);
  EXPECT_EQ(apex_first.a_count, 1);
  expect_oriented_strip(apex_first);

  EXPECT_EQ(twist_minimizing_strip(open_ring, apex).mesh.triangles.size(), 8u);
  EXPECT_EQ(twist_minimizing_strip(apex, open_ring).mesh.triangles.size(), 8u);
}

TEST(TwistDp, PointAgainstPointIsOneDegenerateTriangle) {
  Polyline a;
  Polyline b;
  a.points = {Vec3(0, 0, 0)};
  b.points = {Vec3(1, 0, 0)};
  const RuledStrip strip = twist_minimizing_strip(a, b);
  ASSERT_EQ(strip.mesh.triangles.size(), 1u);
  EXPECT_EQ(strip.mesh.triangles[0], (Triangle{0, 1, 1}));
  EXPECT_EQ(strip.mesh.vertices.size(), 2u);
}

TEST(TwistDp, UvsAreCopiedWhenBothPolylinesHaveThem) {
  Polyline a = square(0.0);
  Polyline b = square(1.0);
  for (int k = 0; k < 4; ++k) {
    a.uvs.emplace_back(0.25 * k, 0.0);
    b.uvs.emplace_back(0.25 * k, 1.0);
  }
  const RuledStrip strip = twist_minimizing_strip(a, b);
  ASSERT_EQ(strip.uvs.size(), 8u);
  EXPECT_EQ(strip.uvs[2], Vec2(0.5, 0.0));
  EXPECT_EQ(strip.uvs[4 + 3], Vec2(0.75, 1.0));
  b.uvs.clear();
  EXPECT_TRUE(twist_minimizing_strip(a, b).uvs.empty());
}

TEST(TwistDp, RejectsBadInput) {
  const Polyline closed = square(0.0);
  Polyline open = square(1.0);
  open.closed = false;
  EXPECT_THROW(twist_minimizing_strip(closed, open), InvalidInputException);
  EXPECT_THROW(twist_minimizing_strip(open, closed), InvalidInputException);
  EXPECT_THROW(twist_minimizing_strip(Polyline{}, closed), InvalidInputException);
  Polyline two;
  two.closed = true;
  two.points = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_THROW(twist_minimizing_strip(two, closed), InvalidInputException);
  Polyline bad_uvs = closed;
  bad_uvs.uvs = {Vec2(0, 0)};
  EXPECT_THROW(twist_minimizing_strip(bad_uvs, closed), InvalidInputException);
  Polyline not_finite = closed;
  not_finite.points[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(twist_minimizing_strip(not_finite, closed), InvalidInputException);
  TwistOptions negative;
  negative.ruling_length_weight = -1.0;
  EXPECT_THROW(twist_minimizing_strip(closed, square(1.0), negative), InvalidInputException);
}

TEST(TwistDp, DegenerateNormalsStayFinite) {
  // Repeated points (zero tangents) and a B that touches A: costs fall back to 1 per ruling.
  Polyline a = square(0.0);
  Polyline b = square(0.0);
  b.points[1] = b.points[0];
  const RuledStrip strip = twist_minimizing_strip(a, b);
  EXPECT_EQ(strip.mesh.triangles.size(), 8u);
  EXPECT_TRUE(std::isfinite(strip.twist_cost));
  EXPECT_GE(strip.twist_cost, 0.0);
}

}  // namespace
}  // namespace papercraft
