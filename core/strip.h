#pragma once
// Strips: the 3D triangulated ruled surfaces (TRS) built by the `ruled` stage and their
// flat images built by `unfold` (DESIGN.md section 4, strips.json).

#include <string>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

/// A strip boundary: an open or closed polyline, or a single point (a cone apex).
/// `uvs` is empty or has one entry per point.
struct Polyline {
  std::vector<Vec3> points;
  std::vector<Vec2> uvs;
  bool closed = false;

  bool is_point() const { return points.size() == 1; }
};

/// A triangulated ruled surface between polyline A and polyline B.
/// Vertices 0..a_count-1 are A's points in order, a_count..a_count+b_count-1 are B's.
/// Every triangle has two vertices on one polyline and one on the other (a ruling is an
/// edge joining A and B). `uvs` is empty or has one entry per vertex.
struct RuledStrip {
  TriangleMesh mesh;
  std::vector<Vec2> uvs;
  int a_count = 0;
  int b_count = 0;
  bool a_closed = false;
  bool b_closed = false;
  double twist_cost = 0.0;  // sum of (1 - <n_a, n_b>) over the rulings
};

/// Kind of a boundary edge of a flat strip.
enum class EdgeKind {
  Cut,   // a cut the user makes without a partner edge (should not occur in a finished model)
  Seam,  // glued to another boundary edge (of another strip or of the same strip)
  Open,  // lies on a boundary of the input mesh: cut, never glued
};

struct BoundaryEdge {
  int v0 = -1;  // vertex indices into the flat strip, v0 -> v1 with the strip on the left
  int v1 = -1;
  EdgeKind kind = EdgeKind::Cut;
  int neighbour_strip = -1;  // id of the flat strip on the other side of a seam
  std::string label;         // the same label is printed on both sides of a seam
  int partner_edge = -1;     // index of the glued edge in that strip's boundary
};

/// One piece of paper: a developed strip. `vertices3d` and `vertices2d` share indexing;
/// 2D coordinates are in model units before page scaling.
struct FlatStrip {
  int id = -1;
  int source_strip = -1;  // id of the 3D strip it was unfolded from
  std::vector<Vec3> vertices3d;
  std::vector<Vec2> vertices2d;
  std::vector<Triangle> triangles;
  std::vector<Vec2> uvs;  // empty or one per vertex
  std::vector<BoundaryEdge> boundary;
};

}  // namespace papercraft
