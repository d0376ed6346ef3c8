// The strips in millimetres with their edge lookups, and the boundary loops of pieces.
#include "nodes/layout/pieces.h"

#include <algorithm>
#include <set>
#include <utility>

#include "core/edge_map.h"
#include "core/errors.h"
#include "core/flat_boundary.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {

std::string piece_name(int number, int index, int count) {
  std::string name = std::to_string(number);
  if (count <= 1) return name;
  std::string letters;
  for (int k = index; k >= 0; k = k / 26 - 1) letters.insert(letters.begin(), char('a' + k % 26));
  return name.append(letters);
}

std::string strip_name(const FlatStrip& strip) {
  return "strip " + std::to_string(strip.id);
}

void validate_strip(const FlatStrip& strip) {
  const std::string name = strip_name(strip);
  const int n = static_cast<int>(strip.vertices2d.size());
  if (strip.vertices3d.size() != strip.vertices2d.size())
    throw InvalidInputException(name + " has " + std::to_string(strip.vertices3d.size()) +
                                " 3D vertices but " + std::to_string(n) + " 2D vertices");
  if (!strip.uvs.empty() && static_cast<int>(strip.uvs.size()) != n)
    throw InvalidInputException(name + " has " + std::to_string(strip.uvs.size()) + " uvs for " +
                                std::to_string(n) + " vertices");
  for (int i = 0; i < n; ++i)
    if (!strip.vertices2d[i].allFinite() || !strip.vertices3d[i].allFinite())
      throw InvalidInputException(name + " vertex " + std::to_string(i) +
                                  " has a non-finite coordinate");
  for (std::size_t t = 0; t < strip.triangles.size(); ++t)
    for (int v : strip.triangles[t])
      if (v < 0 || v >= n)
        throw InvalidInputException(name + " triangle " + std::to_string(t) + " has vertex index " +
                                    std::to_string(v) + " out of range");
  for (const BoundaryEdge& e : strip.boundary)
    if (e.v0 < 0 || e.v0 >= n || e.v1 < 0 || e.v1 >= n)
      throw InvalidInputException(name + " boundary edge " + std::to_string(e.v0) + "-" +
                                  std::to_string(e.v1) + " has a vertex index out of range");
}

StripData prepare_strip(const FlatStrip& strip, double mm_per_unit) {
  StripData data;
  data.strip = &strip;
  for (const Vec2& v : strip.vertices2d) data.points.push_back(v * mm_per_unit);
  const std::string name = strip_name(strip);
  if (const int t = first_clockwise_triangle(strip.vertices2d, strip.triangles, 1e-9); t >= 0)
    throw InvalidInputException(name + " triangle " + std::to_string(t) +
                                " is clockwise in 2D (a mirrored unfolding)");
  for (int t = 0; t < static_cast<int>(strip.triangles.size()); ++t) {
    const Triangle& tri = strip.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
    for (int i = 0; i < 3; ++i) {
      if (!data.owner.emplace(directed_edge_key(tri[i], tri[(i + 1) % 3]), t).second)
        throw InvalidInputException(name + " edge " + std::to_string(tri[i]) + "-" +
                                    std::to_string(tri[(i + 1) % 3]) +
                                    " belongs to two triangles in the same direction");
    }
    data.triangles.push_back(t);
  }
  for (int i = 0; i < static_cast<int>(strip.boundary.size()); ++i) {
    const BoundaryEdge& e = strip.boundary[i];
    const std::uint64_t key = directed_edge_key(e.v0, e.v1);
    if (!data.owner.count(key) || data.owner.count(directed_edge_key(e.v1, e.v0)))
      throw InvalidInputException(name + " boundary edge " + std::to_string(e.v0) + "-" +
                                  std::to_string(e.v1) +
                                  " is not a boundary edge of its triangles with the strip on "
                                  "its left");
    data.boundary_of[key] = i;
  }
  return data;
}

std::vector<Vec2> piece_points(const StripData& data, const std::vector<int>& triangles) {
  std::vector<Vec2> points;
  std::vector<char> seen(data.points.size(), 0);
  for (int t : triangles)
    for (int v : data.strip->triangles[t])
      if (!seen[v]) {
        seen[v] = 1;
        points.push_back(data.points[v]);
      }
  return points;
}

std::vector<std::vector<PieceEdge>> piece_loops(StripData& data, const std::vector<int>& triangles,
                                                std::vector<std::string>& warnings) {
  const FlatStrip& strip = *data.strip;
  std::unordered_map<int, char> in_piece;
  for (int t : triangles) in_piece[t] = 1;
  auto inner = [&](int a, int b) {  // (a, b) has a piece triangle on its right too
    auto it = data.owner.find(directed_edge_key(b, a));
    return it != data.owner.end() && in_piece.count(it->second);
  };
  auto third = [&](int t, int a, int b) {
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i)
      if (tri[i] == a && tri[(i + 1) % 3] == b) return tri[(i + 2) % 3];
    return -1;
  };
  std::vector<std::pair<int, int>> edges;
  for (int t : triangles) {
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i)
      if (!inner(tri[i], tri[(i + 1) % 3])) edges.emplace_back(tri[i], tri[(i + 1) % 3]);
  }
  std::sort(edges.begin(), edges.end());
  std::set<std::pair<int, int>> used;
  std::vector<std::vector<PieceEdge>> loops;
  for (const auto& start : edges) {
    if (used.count(start)) continue;
    std::vector<PieceEdge> loop;
    std::pair<int, int> current = start;
    while (!used.count(current)) {
      used.insert(current);
      PieceEdge edge;
      edge.v0 = current.first;
      edge.v1 = current.second;
      const std::uint64_t key = directed_edge_key(edge.v0, edge.v1);
      if (auto b = data.boundary_of.find(key); b != data.boundary_of.end()) {
        const BoundaryEdge& given = strip.boundary[b->second];
        edge.kind = given.kind;
        if (given.kind == EdgeKind::Seam) edge.label = given.label;
      } else if (auto s = data.split_label.find(
                     directed_edge_key(std::min(edge.v0, edge.v1), std::max(edge.v0, edge.v1)));
                 s != data.split_label.end()) {
        edge.kind = EdgeKind::Seam;
        edge.label = s->second;
      } else if (!data.owner.count(directed_edge_key(edge.v1, edge.v0)) &&
                 !data.missing_boundary_warned) {
        data.missing_boundary_warned = true;
        warnings.push_back(strip_name(strip) + ": boundary edge " + std::to_string(edge.v0) + "-" +
                           std::to_string(edge.v1) +
                           " is missing from its boundary list; drawn as a plain cut");
      }
      loop.push_back(edge);
      // Rotate around v1 through the piece's triangles to the next boundary edge.
      int a = current.first, b = current.second;
      int t = data.owner.at(directed_edge_key(a, b));
      std::pair<int, int> next{-1, -1};
      for (std::size_t guard = 0; guard <= triangles.size(); ++guard) {
        const int c = third(t, a, b);
        if (!inner(b, c)) {
          next = {b, c};
          break;
        }
        t = data.owner.at(directed_edge_key(c, b));
        a = c;
      }
      if (next.first < 0) break;
      current = next;
    }
    loops.push_back(std::move(loop));
  }
  auto loop_area = [&](const std::vector<PieceEdge>& loop) {
    std::vector<Vec2> polygon;
    for (const PieceEdge& e : loop) polygon.push_back(data.points[e.v0]);
    return signed_area(polygon);
  };
  std::stable_sort(loops.begin(), loops.end(),
                   [&](const auto& a, const auto& b) { return loop_area(a) > loop_area(b); });
  return loops;
}

}  // namespace papercraft::layout_internal
