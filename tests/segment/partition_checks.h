#pragma once
// Checks shared by the segmentation tests: the parts partition the input, each is a connected
// 2-manifold carrying "v:input_vertex", and neighbouring parts meet edge to edge.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/generate.h"
#include "core/mesh.h"
#include "nodes/segment/none.h"

namespace papercraft::testing {

inline Mesh tagged_mesh(const TriangleMesh& shape) {
  Mesh mesh = to_mesh(shape);
  tag_input_vertices(mesh);
  return mesh;
}

using PointKey = std::array<double, 3>;

inline PointKey key_of(const OpenMesh::Vec3d& p) {
  return {p[0], p[1], p[2]};
}

// Areas add up, no input face is used twice, every part is a connected 2-manifold whose
// vertices carry "v:input_vertex", and input vertices keep their exact coordinates.
inline void expect_partition(const Mesh& input, const std::vector<Mesh>& parts) {
  double area = 0;
  std::set<std::array<int, 3>> input_faces;
  for (auto f : input.faces()) {
    std::array<int, 3> corners{};
    int k = 0;
    for (auto v : f.vertices()) corners[k++] = v.idx();
    std::sort(corners.begin(), corners.end());
    input_faces.insert(corners);
  }
  std::set<std::array<int, 3>> whole_faces_seen;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Mesh& part = parts[p];
    SCOPED_TRACE("part " + std::to_string(p));
    area += surface_area(part);
    EXPECT_GT(part.n_faces(), 0u);
    EXPECT_EQ(connected_components(part), 1);
    for (auto v : part.vertices()) EXPECT_TRUE(part.is_manifold(v)) << "vertex " << v.idx();
    OpenMesh::VPropHandleT<int> input_vertex;
    ASSERT_TRUE(part.get_property_handle(input_vertex, kInputVertexProperty));
    for (auto v : part.vertices()) {
      const int original = part.property(input_vertex, v);
      if (original < 0) continue;
      ASSERT_LT(original, static_cast<int>(input.n_vertices()));
      EXPECT_EQ(part.point(v), input.point(Mesh::VertexHandle(original)));
    }
    for (auto f : part.faces()) {
      std::array<int, 3> corners{};
      int k = 0;
      for (auto v : f.vertices()) corners[k++] = part.property(input_vertex, v);
      std::sort(corners.begin(), corners.end());
      if (corners[0] < 0 || !input_faces.count(corners)) continue;
      EXPECT_TRUE(whole_faces_seen.insert(corners).second)
          << "input face " << corners[0] << "-" << corners[1] << "-" << corners[2] << " twice";
    }
  }
  EXPECT_NEAR(area, surface_area(input), 1e-9 * surface_area(input));
}

// On a closed input: every boundary halfedge p -> q of a part is matched by exactly one
// halfedge q -> p of another part (same coordinates bit for bit, so no T-junction).
inline void expect_boundaries_match(const std::vector<Mesh>& parts) {
  std::map<std::pair<PointKey, PointKey>, std::vector<int>> halfedges;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    for (auto h : parts[p].halfedges()) {
      if (!h.is_boundary()) continue;
      // The boundary halfedge runs against the part's own face.
      halfedges[{key_of(parts[p].point(h.to())), key_of(parts[p].point(h.from()))}].push_back(
          static_cast<int>(p));
    }
  }
  for (const auto& [edge, owners] : halfedges) {
    ASSERT_EQ(owners.size(), 1u);
    auto twin = halfedges.find({edge.second, edge.first});
    ASSERT_NE(twin, halfedges.end()) << "boundary edge without a partner in another part";
    ASSERT_EQ(twin->second.size(), 1u);
    EXPECT_NE(twin->second[0], owners[0]);
  }
}

inline void expect_same_parts(const std::vector<Mesh>& a, const std::vector<Mesh>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t p = 0; p < a.size(); ++p) {
    ASSERT_EQ(a[p].n_vertices(), b[p].n_vertices());
    ASSERT_EQ(a[p].n_faces(), b[p].n_faces());
    for (auto v : a[p].vertices()) EXPECT_EQ(a[p].point(v), b[p].point(v));
    const TriangleMesh ta = to_triangle_mesh(a[p]);
    const TriangleMesh tb = to_triangle_mesh(b[p]);
    EXPECT_EQ(ta.triangles, tb.triangles);
  }
}

}  // namespace papercraft::testing
