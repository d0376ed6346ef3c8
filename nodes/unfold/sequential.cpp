#include "nodes/unfold/sequential.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "core/overlap_2d.h"

namespace papercraft {
namespace {

struct FlatBuilder {
  FlatStrip flat;
  TriangleGrid2 grid;
};

void validate(const RuledStrip& strip, const UnfoldOptions& options) {
  const int vertex_count = static_cast<int>(strip.mesh.vertices.size());
  if (strip.a_count < 0 || strip.b_count < 0 ||
      (strip.a_count + strip.b_count != vertex_count && (strip.a_count || strip.b_count)))
    throw InvalidInputException(
        "unfold: strip has " + std::to_string(vertex_count) +
        " vertices but a_count + b_count = " + std::to_string(strip.a_count + strip.b_count));
  if (!strip.uvs.empty() && static_cast<int>(strip.uvs.size()) != vertex_count)
    throw InvalidInputException("unfold: strip has " + std::to_string(strip.uvs.size()) +
                                " uvs for " + std::to_string(vertex_count) + " vertices");
  for (int v = 0; v < vertex_count; ++v)
    if (!strip.mesh.vertices[v].allFinite())
      throw InvalidInputException("unfold: vertex " + std::to_string(v) +
                                  " has a non-finite coordinate");
  for (std::size_t t = 0; t < strip.mesh.triangles.size(); ++t)
    for (int v : strip.mesh.triangles[t])
      if (v < 0 || v >= vertex_count)
        throw InvalidInputException("unfold: triangle " + std::to_string(t) + " has vertex " +
                                    std::to_string(v) + " out of range [0, " +
                                    std::to_string(vertex_count) + ")");
  if (!(options.overlap_tolerance >= 0.0) || !(options.ruling_tie_tolerance >= 0.0))
    throw InvalidInputException("unfold: tolerances must be >= 0");
}

// 2D position of c for the 3D triangle (a3, b3, c3) with a and b already at a2 and b2,
// on the left of a2 -> b2, from the foot of c on line ab and c's height over it (both
// exact 3D quantities, which keeps thin triangles accurate). Across a zero-length edge the
// triangle has no defined hinge; it is laid straight on along `fallback`.
Vec2 place_third(const Vec3& a3, const Vec3& b3, const Vec3& c3, const Vec2& a2, const Vec2& b2,
                 const Vec2& fallback) {
  Vec3 ab = b3 - a3, ac = c3 - a3;
  double length3 = ab.norm();
  Vec2 edge = b2 - a2;
  double length2 = edge.norm();
  if (length3 == 0.0 || length2 == 0.0) {
    double norm = fallback.norm();
    Vec2 direction = norm > 0.0 ? Vec2(fallback / norm) : Vec2(1.0, 0.0);
    return a2 + ac.norm() * direction;
  }
  double along = ac.dot(ab) / length3;
  double height = ab.cross(ac).norm() / length3;
  Vec2 e = edge / length2;
  Vec2 n(-e.y(), e.x());
  return a2 + along * e + height * n;
}

}  // namespace

std::vector<FlatStrip> unfold_strip(const RuledStrip& strip, int source_strip_id, int first_flat_id,
                                    const UnfoldOptions& options) {
  validate(strip, options);
  const auto& vertices = strip.mesh.vertices;
  const auto& triangles = strip.mesh.triangles;
  const int triangle_count = static_cast<int>(triangles.size());

  std::vector<bool> usable(triangle_count);
  for (int t = 0; t < triangle_count; ++t) {
    const Triangle& tri = triangles[t];
    usable[t] = tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0];
  }

  // Dual graph: neighbour[t][i] is the triangle across edge (t[i], t[i+1]).
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edge_faces;
  double edge_length_sum = 0.0;
  int edge_count = 0;
  for (int t = 0; t < triangle_count; ++t) {
    if (!usable[t]) continue;
    for (int i = 0; i < 3; ++i) {
      int u = triangles[t][i], v = triangles[t][(i + 1) % 3];
      edge_faces[{std::min(u, v), std::max(u, v)}].push_back({t, i});
      edge_length_sum += (vertices[v] - vertices[u]).norm();
      ++edge_count;
    }
  }
  std::vector<std::array<int, 3>> neighbour(triangle_count, {-1, -1, -1});
  std::vector<std::pair<int, int>> dual_edges;  // keys of edges with a dual link
  for (const auto& [key, faces] : edge_faces) {
    if (faces.size() != 2) continue;
    auto [t0, i0] = faces[0];
    auto [t1, i1] = faces[1];
    if (triangles[t0][i0] != triangles[t1][(i1 + 1) % 3]) continue;  // same direction twice
    neighbour[t0][i0] = t1;
    neighbour[t1][i1] = t0;
    dual_edges.push_back(key);
  }

  // Open a closed strip along its shortest ruling (an edge joining A and B).
  const bool closed = (strip.a_closed && (strip.b_closed || strip.b_count == 1)) ||
                      (strip.b_closed && strip.a_count == 1);
  if (closed) {
    double shortest = std::numeric_limits<double>::infinity();
    for (const auto& [u, v] : dual_edges)
      if ((u < strip.a_count) != (v < strip.a_count))
        shortest = std::min(shortest, (vertices[u] - vertices[v]).norm());
    for (const auto& [u, v] : dual_edges) {  // sorted by (u, v): the first tied ruling wins
      if ((u < strip.a_count) == (v < strip.a_count)) continue;
      if ((vertices[u] - vertices[v]).norm() > shortest * (1.0 + options.ruling_tie_tolerance))
        continue;
      for (auto [t, i] : edge_faces.at({u, v})) neighbour[t][i] = -1;
      break;
    }
  }

  const double mean_edge = edge_count > 0 ? edge_length_sum / edge_count : 0.0;
  const double cell_size = mean_edge > 0.0 ? mean_edge : 1.0;
  const double tolerance = options.overlap_tolerance * mean_edge;

  std::vector<FlatBuilder> builders;
  std::vector<int> flat_of(triangle_count, -1);            // flat strip of a placed triangle
  std::vector<std::array<int, 3>> corner(triangle_count);  // flat vertex of each corner
  auto add_vertex = [&](FlatBuilder& builder, int source, const Vec2& position) {
    builder.flat.vertices3d.push_back(vertices[source]);
    builder.flat.vertices2d.push_back(position);
    if (!strip.uvs.empty()) builder.flat.uvs.push_back(strip.uvs[source]);
    return static_cast<int>(builder.flat.vertices2d.size()) - 1;
  };
  auto start_flat = [&]() {
    builders.push_back(FlatBuilder{FlatStrip{}, TriangleGrid2(cell_size)});
    return static_cast<int>(builders.size()) - 1;
  };
  auto commit = [&](int f, int t, const std::array<int, 3>& corners, const Triangle2& image) {
    builders[f].flat.triangles.push_back({corners[0], corners[1], corners[2]});
    builders[f].grid.insert(image);
    flat_of[t] = f;
    corner[t] = corners;
  };

  // Roots: triangles with at most one dual neighbour first (the ends of a strip), in order.
  std::vector<int> roots;
  for (int pass = 0; pass < 2; ++pass) {
    for (int t = 0; t < triangle_count; ++t) {
      if (!usable[t]) continue;
      int degree =
          std::count_if(neighbour[t].begin(), neighbour[t].end(), [](int n) { return n >= 0; });
      if ((degree <= 1) == (pass == 0)) roots.push_back(t);
    }
  }

  std::vector<bool> queued(triangle_count, false);
  for (int root : roots) {
    if (queued[root]) continue;
    {
      // Longest edge first along +x, so a thin triangle gets a well-defined frame.
      const Triangle& tri = triangles[root];
      int r = 0;
      double longest = -1.0;
      for (int i = 0; i < 3; ++i) {
        double length = (vertices[tri[(i + 1) % 3]] - vertices[tri[i]]).norm();
        if (length > longest) longest = length, r = i;
      }
      int a = tri[r], b = tri[(r + 1) % 3], c = tri[(r + 2) % 3];
      Vec2 a2(0.0, 0.0), b2(longest, 0.0);
      Vec2 c2 = place_third(vertices[a], vertices[b], vertices[c], a2, b2, Vec2(0.0, 1.0));
      int f = start_flat();
      std::array<int, 3> corners;
      corners[r] = add_vertex(builders[f], a, a2);
      corners[(r + 1) % 3] = add_vertex(builders[f], b, b2);
      corners[(r + 2) % 3] = add_vertex(builders[f], c, c2);
      Triangle2 image;
      image[r] = a2, image[(r + 1) % 3] = b2, image[(r + 2) % 3] = c2;
      commit(f, root, corners, image);
    }
    queued[root] = true;
    std::deque<int> queue{root};
    while (!queue.empty()) {
      int parent = queue.front();
      queue.pop_front();
      for (int j = 0; j < 3; ++j) {
        int t = neighbour[parent][j];
        if (t < 0 || queued[t]) continue;
        queued[t] = true;
        queue.push_back(t);
        // The shared edge is (p_j, p_j+1) in the parent and (a, b) = (p_j+1, p_j) in t.
        const Triangle& tri = triangles[t];
        int i = 0;
        while (neighbour[t][i] != parent || tri[i] != triangles[parent][(j + 1) % 3]) ++i;
        int a = tri[i], b = tri[(i + 1) % 3], c = tri[(i + 2) % 3];
        const FlatStrip& parent_flat = builders[flat_of[parent]].flat;
        int fa = corner[parent][(j + 1) % 3], fb = corner[parent][j];
        Vec2 a2 = parent_flat.vertices2d[fa], b2 = parent_flat.vertices2d[fb];
        Vec2 p2 = parent_flat.vertices2d[corner[parent][(j + 2) % 3]];
        Vec2 c2 = place_third(vertices[a], vertices[b], vertices[c], a2, b2, a2 - p2);
        Triangle2 image;
        image[i] = a2, image[(i + 1) % 3] = b2, image[(i + 2) % 3] = c2;

        int f = flat_of[parent];
        std::array<int, 3> corners;
        if (builders[f].grid.overlaps(image, tolerance)) {
          f = start_flat();
          corners[i] = add_vertex(builders[f], a, a2);
          corners[(i + 1) % 3] = add_vertex(builders[f], b, b2);
        } else {
          corners[i] = fa;
          corners[(i + 1) % 3] = fb;
        }
        corners[(i + 2) % 3] = add_vertex(builders[f], c, c2);
        commit(f, t, corners, image);
      }
    }
  }

  std::vector<FlatStrip> result;
  result.reserve(builders.size());
  for (std::size_t k = 0; k < builders.size(); ++k) {
    FlatStrip& flat = builders[k].flat;
    flat.id = first_flat_id + static_cast<int>(k);
    flat.source_strip = source_strip_id;
    flat.boundary = flat_boundary(flat.triangles);
    result.push_back(std::move(flat));
  }
  return result;
}

}  // namespace papercraft
