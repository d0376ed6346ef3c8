// build_strip: the ruled strip faces the way its part does, so that it unfolds into its piece
// and not into the piece's mirror image, and its seams run against their partners'.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "core/generate.h"
#include "engine/refine/refine.h"

namespace papercraft {
namespace {

// Judged apart from build_strip: the strip's boundary edges (directed, strip on the left)
// found among the part's boundary edges by their end points. `agree`: the part's face lies on
// the left of the same directed edge, as the strip does; `against`: on its right.
struct Facing {
  int agree = 0;
  int against = 0;
};

Facing facing(const Mesh& part, const RuledStrip& strip) {
  std::map<std::array<double, 3>, int> vertex_at;
  for (auto v : part.vertices()) {
    const auto& p = part.point(v);
    vertex_at[{p[0], p[1], p[2]}] = v.idx();
  }
  auto vertex = [&](int i) {
    const Vec3& p = strip.mesh.vertices[i];
    const auto it = vertex_at.find({p.x(), p.y(), p.z()});
    return it == vertex_at.end() ? -1 : it->second;
  };
  std::set<std::pair<int, int>> directed;
  for (const Triangle& t : strip.mesh.triangles)
    for (int k = 0; k < 3; ++k) directed.insert({t[k], t[(k + 1) % 3]});
  Facing f;
  for (const auto& [s, e] : directed) {
    if (directed.count({e, s})) continue;  // an inner edge of the strip
    const int u = vertex(s), v = vertex(e);
    if (u < 0 || v < 0 || u == v) continue;
    const auto h = part.find_halfedge(part.vertex_handle(u), part.vertex_handle(v));
    if (!h.is_valid() || !part.is_boundary(part.edge_handle(h))) continue;
    (part.is_boundary(h) ? f.against : f.agree) += 1;
  }
  return f;
}

// A band of an open cylinder, 32 segments round, its two loops the strip's boundaries.
Mesh band() {
  OpenCylinderOptions options;
  options.height = 0.2;
  options.rings = 1;
  return to_mesh(open_cylinder(options));
}

TEST(BuildStrip, TheTraversalOfBThatTurnsTheStripInsideOutIsNotKept) {
  const Mesh part = band();
  const StripBoundaries boundaries = select_strip_boundaries(part, at_tolerance({}, 0.01));
  ASSERT_TRUE(boundaries.a.closed && boundaries.b.closed);
  // Each traversal of B forced on the twist search: one of them makes a strip whose B side
  // faces the other way (the case build_strip must catch), the other the right strip.
  int inside_out = 0;
  for (int direction : {1, -1}) {
    SCOPED_TRACE(direction);
    RefineOptions options;
    options.twist.b_direction = direction;
    const Facing raw =
        facing(part, twist_minimizing_strip(boundaries.a, boundaries.b, options.twist));
    inside_out += raw.against > 0 ? 1 : 0;
    const RuledStrip strip = build_strip(part, boundaries, options);
    const Facing built = facing(part, strip);
    EXPECT_EQ(built.against, 0);
    EXPECT_EQ(built.agree, 64);  // both loops, 32 edges each
  }
  EXPECT_EQ(inside_out, 1);
}

TEST(BuildStrip, AStripFacingTheOtherWayAllOverIsTurnedOver) {
  // The part's loops taken the other way round: the strip follows A, so it faces the other
  // way on both loops; and a fan from the far end of a disc taken the same way.
  const Mesh part = band();
  StripBoundaries boundaries = select_strip_boundaries(part, at_tolerance({}, 0.01));
  for (auto* side : {&boundaries.first, &boundaries.second})
    std::reverse(side->begin(), side->end());
  for (auto* line : {&boundaries.a, &boundaries.b}) {
    std::reverse(line->points.begin(), line->points.end());
    std::reverse(line->uvs.begin(), line->uvs.end());
  }
  const Facing raw = facing(part, twist_minimizing_strip(boundaries.a, boundaries.b, {}));
  EXPECT_EQ(raw.agree, 0);
  EXPECT_EQ(raw.against, 64);
  const Facing built = facing(part, build_strip(part, boundaries, {}));
  EXPECT_EQ(built.against, 0);
  EXPECT_EQ(built.agree, 64);

  TriangleMesh disc_mesh;  // a hexagon fanned from its centre
  disc_mesh.vertices.push_back(Vec3::Zero());
  for (int k = 0; k < 6; ++k)
    disc_mesh.vertices.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0.0);
  for (int k = 0; k < 6; ++k) disc_mesh.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  const Mesh disc = to_mesh(disc_mesh);
  StripBoundaries fan = select_strip_boundaries(disc, at_tolerance({}, 0.01));
  ASSERT_TRUE(fan.a.is_point() || fan.b.is_point());
  for (auto* side : {&fan.first, &fan.second}) std::reverse(side->begin(), side->end());
  for (auto* line : {&fan.a, &fan.b}) std::reverse(line->points.begin(), line->points.end());
  EXPECT_EQ(facing(disc, twist_minimizing_strip(fan.a, fan.b, {})).agree, 0);
  const Facing turned = facing(disc, build_strip(disc, fan, {}));
  EXPECT_EQ(turned.against, 0);
  EXPECT_EQ(turned.agree, 6);
}

}  // namespace
}  // namespace papercraft
