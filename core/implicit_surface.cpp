// Marching tetrahedra and the remeshing of an implicit surface (implicit_surface.h).
#include "core/implicit_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "core/mesh.h"

namespace papercraft {

TriangleMesh marching_tetrahedra(const ImplicitGrid& grid) {
  // Corner c of a cube has offset (c & 1, c >> 1 & 1, c >> 2 & 1); the 6 tetrahedra are the
  // monotone paths 0 -> a -> a|b -> 7 over the axis permutations (a, b, c), which agree on
  // shared faces of neighbouring cubes.
  const std::array<std::array<int, 3>, 6> permutations = {
      {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}}};
  auto offset = [](int corner) { return Vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1); };

  TriangleMesh mesh;
  // A surface vertex lies on the lattice edge from node n along direction d (a non-empty
  // subset of the axes, always positive): key n * 8 + d.
  std::unordered_map<std::int64_t, int> edge_vertex;
  std::array<std::int64_t, 8> corner_node{};
  std::array<double, 8> corner_value{};
  std::array<Vec3, 8> corner_position;

  auto vertex_on = [&](int corner_a, int corner_b) {
    if (corner_a > corner_b) std::swap(corner_a, corner_b);
    // On a monotone path corner_a's bits are a subset of corner_b's.
    const std::int64_t key = corner_node[corner_a] * 8 + (corner_b ^ corner_a);
    auto [it, inserted] = edge_vertex.try_emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) {
      const double fa = corner_value[corner_a], fb = corner_value[corner_b];
      const double t = fa / (fa - fb);
      mesh.vertices.push_back(corner_position[corner_a] +
                              t * (corner_position[corner_b] - corner_position[corner_a]));
    }
    return it->second;
  };
  auto orientation = [&](int a, int b, int c, int d) {
    return (offset(b) - offset(a)).cross(offset(c) - offset(a)).dot(offset(d) - offset(a));
  };

  for (int z = 0; z + 1 < grid.nodes[2]; ++z) {
    for (int y = 0; y + 1 < grid.nodes[1]; ++y) {
      for (int x = 0; x + 1 < grid.nodes[0]; ++x) {
        int inside_count = 0;
        for (int c = 0; c < 8; ++c) {
          const int cx = x + (c & 1), cy = y + ((c >> 1) & 1), cz = z + ((c >> 2) & 1);
          corner_node[c] = grid.node_index(cx, cy, cz);
          corner_value[c] = grid.values[corner_node[c]];
          inside_count += corner_value[c] < 0.0;
        }
        if (inside_count == 0 || inside_count == 8) continue;
        for (int c = 0; c < 8; ++c) {
          corner_position[c] = grid.position(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1));
        }
        for (const auto& p : permutations) {
          const std::array<int, 4> tet = {0, p[0], p[0] | p[1], 7};
          std::vector<int> inside, outside;
          for (int corner : tet) (corner_value[corner] < 0.0 ? inside : outside).push_back(corner);
          if (inside.empty() || outside.empty()) continue;
          if (inside.size() == 2) {
            const int a = inside[0], b = inside[1], c = outside[0], d = outside[1];
            std::array<int, 4> quad = {vertex_on(a, c), vertex_on(b, c), vertex_on(b, d),
                                       vertex_on(a, d)};
            // (ac, bc, bd, ad) faces towards the inside corners when (a, b, c, d) is positive.
            if (orientation(a, b, c, d) > 0.0) std::reverse(quad.begin(), quad.end());
            const auto& v = mesh.vertices;
            if ((v[quad[0]] - v[quad[2]]).squaredNorm() <=
                (v[quad[1]] - v[quad[3]]).squaredNorm()) {
              mesh.triangles.push_back({quad[0], quad[1], quad[2]});
              mesh.triangles.push_back({quad[0], quad[2], quad[3]});
            } else {
              mesh.triangles.push_back({quad[1], quad[2], quad[3]});
              mesh.triangles.push_back({quad[1], quad[3], quad[0]});
            }
            continue;
          }
          const bool lone_inside = inside.size() == 1;
          const int lone = lone_inside ? inside[0] : outside[0];
          const std::vector<int>& others = lone_inside ? outside : inside;
          Triangle triangle = {vertex_on(lone, others[0]), vertex_on(lone, others[1]),
                               vertex_on(lone, others[2])};
          // The triangle faces away from `lone` iff (lone, others...) is positively oriented;
          // it must face away from the inside.
          const bool faces_away = orientation(lone, others[0], others[1], others[2]) > 0.0;
          if (faces_away != lone_inside) std::swap(triangle[1], triangle[2]);
          mesh.triangles.push_back(triangle);
        }
      }
    }
  }
  return mesh;
}

namespace {

constexpr double kPi = std::numbers::pi;

// Remeshing of a polygonised implicit surface towards edge length target_length, after the
// isotropic remeshing of Botsch & Kobbelt 2004 without splits: collapse short edges, flip
// edges to raise the smaller angle, relax vertices tangentially and project them back onto
// the zero set. Collapses pass OpenMesh's is_collapse_ok (the link condition, which keeps
// the topology; Dey et al. 1999) and flips pass is_flip_ok, so the result stays a closed
// manifold of the same genus; every step is refused if it would leave a face more than 45
// degrees away from the field's gradient, which keeps out folds and zero-area faces.
class ImplicitRemesher {
 public:
  ImplicitRemesher(const TriangleMesh& input, std::function<double(const Vec3&)> field,
                   double target_length)
      : mesh_(to_mesh(input)),
        field_(std::move(field)),
        low_(0.8 * target_length),
        high_(4.0 / 3.0 * target_length),
        step_(1e-4 * target_length) {}

  TriangleMesh run(int rounds) {
    for (int round = 0; round < rounds; ++round) {
      collapse_short_edges();
      flip_edges();
      relax_vertices();
      flip_edges();
    }
    mesh_.garbage_collection();
    return to_triangle_mesh(mesh_);
  }

 private:
  Vec3 point(Mesh::VertexHandle v) const { return to_eigen(mesh_.point(v)); }

  static Vec3 normal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

  // Would moving `moved` to `position` keep every face around it within 45 degrees of the
  // surface normal? Faces containing `ignored` are skipped (they vanish in a collapse).
  bool move_keeps_faces(Mesh::VertexHandle moved, const Vec3& position,
                        Mesh::VertexHandle ignored = Mesh::VertexHandle()) const {
    for (auto face : mesh_.vf_range(moved)) {
      std::array<Vec3, 3> corner;
      int k = 0;
      bool skip = false;
      for (auto v : mesh_.fv_range(face)) {
        skip = skip || v == ignored;
        corner[k++] = v == moved ? position : point(v);
      }
      if (skip) continue;
      const Vec3 center = (corner[0] + corner[1] + corner[2]) / 3.0;
      if (!within_maximum_turn(normal(corner[0], corner[1], corner[2]), gradient(center))) {
        return false;
      }
    }
    return true;
  }

  void collapse_short_edges() {
    for (bool changed = true; changed;) {
      changed = false;
      std::vector<std::pair<double, Mesh::EdgeHandle>> short_edges;
      for (auto e : mesh_.edges()) {
        if (mesh_.status(e).deleted()) continue;
        const double length = mesh_.calc_edge_length(e);
        if (length < low_) short_edges.emplace_back(length, e);
      }
      std::sort(short_edges.begin(), short_edges.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (const auto& [length, e] : short_edges) {
        if (mesh_.status(e).deleted() || mesh_.calc_edge_length(e) >= low_) continue;
        for (auto h : {mesh_.halfedge_handle(e, 0), mesh_.halfedge_handle(e, 1)}) {
          const auto removed = mesh_.from_vertex_handle(h), kept = mesh_.to_vertex_handle(h);
          if (!mesh_.is_collapse_ok(h)) continue;
          bool short_enough = true;
          for (auto neighbour : mesh_.vv_range(removed)) {
            short_enough = short_enough && (point(neighbour) - point(kept)).norm() <= high_;
          }
          if (short_enough && move_keeps_faces(removed, point(kept), kept)) {
            mesh_.collapse(h);
            changed = true;
            break;
          }
        }
      }
    }
  }

  static double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const std::array<Vec3, 3> p = {a, b, c};
    double smallest = kPi;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
      smallest = std::min(smallest, std::atan2(u.cross(w).norm(), u.dot(w)));
    }
    return smallest;
  }

  // Flips an edge when the flip raises the smaller of its two triangles' smallest angles (a
  // local Delaunay criterion) and both new faces lie within 45 degrees of the surface normal
  // (the field's gradient; the old faces' normals are unreliable when one is a sliver).
  void flip_edges() {
    for (int pass = 0; pass < 5; ++pass) {
      bool changed = false;
      for (auto e : mesh_.edges()) {
        if (mesh_.status(e).deleted() || !mesh_.is_flip_ok(e)) continue;
        const auto h = mesh_.halfedge_handle(e, 0);
        const auto o = mesh_.opposite_halfedge_handle(h);
        const Vec3 a = point(mesh_.from_vertex_handle(h)), b = point(mesh_.to_vertex_handle(h));
        const Vec3 c = point(mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h)));
        const Vec3 d = point(mesh_.to_vertex_handle(mesh_.next_halfedge_handle(o)));
        // Faces (a, b, c) and (b, a, d) become (a, d, c) and (d, b, c).
        const double before = std::min(smallest_angle(a, b, c), smallest_angle(b, a, d));
        const double after = std::min(smallest_angle(a, d, c), smallest_angle(d, b, c));
        if (after <= before + 1e-6) continue;
        const Vec3 surface_normal = gradient(0.25 * (a + b + c + d));
        if (!within_maximum_turn(normal(a, d, c), surface_normal) ||
            !within_maximum_turn(normal(d, b, c), surface_normal)) {
          continue;
        }
        mesh_.flip(e);
        changed = true;
      }
      if (!changed) break;
    }
  }

  static bool within_maximum_turn(const Vec3& n0, const Vec3& n1) {
    return n0.dot(n1) > kCosMaximumTurn * n0.norm() * n1.norm();
  }

  Vec3 gradient(const Vec3& p) const {
    Vec3 g;
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 d = Vec3::Zero();
      d[axis] = step_;
      g[axis] = (field_(p + d) - field_(p - d)) / (2.0 * step_);
    }
    return g;
  }

  Vec3 project(Vec3 p) const {
    for (int iteration = 0; iteration < 3; ++iteration) {
      const Vec3 g = gradient(p);
      const double squared = g.squaredNorm();
      if (squared < 1e-12) break;
      Vec3 move = -field_(p) / squared * g;
      if (move.norm() > low_) move *= low_ / move.norm();
      p += move;
    }
    return p;
  }

  void relax_vertices() {
    for (auto v : mesh_.vertices()) {
      if (mesh_.status(v).deleted()) continue;
      Vec3 centroid = Vec3::Zero();
      int count = 0;
      for (auto w : mesh_.vv_range(v)) {
        centroid += point(w);
        ++count;
      }
      if (count == 0) continue;
      const Vec3 p = point(v);
      Vec3 n = gradient(p);
      if (n.squaredNorm() < 1e-12) continue;
      n.normalize();
      Vec3 move = centroid / count - p;
      move -= move.dot(n) * n;
      const Vec3 target = project(p + move);
      if (move_keeps_faces(v, target)) mesh_.set_point(v, to_openmesh(target));
    }
  }

  static constexpr double kCosMaximumTurn = 0.70710678118654752;  // cos 45 degrees
  Mesh mesh_;
  std::function<double(const Vec3&)> field_;
  double low_, high_, step_;
};

}  // namespace

TriangleMesh remesh_implicit_surface(const TriangleMesh& input,
                                     std::function<double(const Vec3&)> field, double target_length,
                                     int rounds) {
  return ImplicitRemesher(input, std::move(field), target_length).run(rounds);
}

}  // namespace papercraft
