#include "engine/unfold/sequential.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "core/overlap_2d.h"
#include "core/union_find.h"

namespace papercraft {
namespace {

// Two copies of one 3D point lie together on paper when within this times the mean edge.
constexpr double kRepeatedPointReach = 1e-6;

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

// Places the triangles of `run` (each sharing an edge with the one before it) into `builder`,
// the first with its longest edge along +x; returns how many were placed before one would
// overlap the others (run.size() when none does).
std::size_t place_run(const RuledStrip& strip, const std::vector<std::array<int, 3>>& neighbour,
                      const std::vector<int>& run, FlatBuilder& builder, double tolerance) {
  const auto& vertices = strip.mesh.vertices;
  const auto& triangles = strip.mesh.triangles;
  auto add_vertex = [&](int source, const Vec2& position) {
    builder.flat.vertices3d.push_back(vertices[source]);
    builder.flat.vertices2d.push_back(position);
    if (!strip.uvs.empty()) builder.flat.uvs.push_back(strip.uvs[source]);
    return static_cast<int>(builder.flat.vertices2d.size()) - 1;
  };
  std::array<int, 3> previous_corners{};
  for (std::size_t k = 0; k < run.size(); ++k) {
    const int t = run[k];
    const Triangle& tri = triangles[t];
    std::array<int, 3> corners;
    Triangle2 image;
    if (k == 0) {
      int r = 0;
      double longest = -1.0;
      for (int i = 0; i < 3; ++i) {
        const double length = (vertices[tri[(i + 1) % 3]] - vertices[tri[i]]).norm();
        if (length > longest) longest = length, r = i;
      }
      const int a = tri[r], b = tri[(r + 1) % 3], c = tri[(r + 2) % 3];
      const Vec2 a2(0.0, 0.0), b2(longest, 0.0);
      const Vec2 c2 = place_third(vertices[a], vertices[b], vertices[c], a2, b2, Vec2(0.0, 1.0));
      image[r] = a2, image[(r + 1) % 3] = b2, image[(r + 2) % 3] = c2;
      corners[r] = add_vertex(a, a2);
      corners[(r + 1) % 3] = add_vertex(b, b2);
      corners[(r + 2) % 3] = add_vertex(c, c2);
    } else {
      const int parent = run[k - 1];
      int j = 0;
      while (j < 3 && neighbour[parent][j] != t) ++j;
      int i = 0;
      while (i < 3 && (neighbour[t][i] != parent || tri[i] != triangles[parent][(j + 1) % 3])) ++i;
      if (j == 3 || i == 3) return k;  // not adjacent: cannot happen on a path
      const int a = tri[i], b = tri[(i + 1) % 3], c = tri[(i + 2) % 3];
      const int fa = previous_corners[(j + 1) % 3], fb = previous_corners[j];
      const Vec2 a2 = builder.flat.vertices2d[fa], b2 = builder.flat.vertices2d[fb];
      const Vec2 p2 = builder.flat.vertices2d[previous_corners[(j + 2) % 3]];
      const Vec2 c2 = place_third(vertices[a], vertices[b], vertices[c], a2, b2, a2 - p2);
      image[i] = a2, image[(i + 1) % 3] = b2, image[(i + 2) % 3] = c2;
      if (builder.grid.overlaps(image, tolerance)) return k;
      corners[i] = fa;
      corners[(i + 1) % 3] = fb;
      corners[(i + 2) % 3] = add_vertex(c, c2);
    }
    builder.flat.triangles.push_back({corners[0], corners[1], corners[2]});
    builder.grid.insert(image);
    previous_corners = corners;
  }
  return run.size();
}

// For a strip whose triangles form one path (a ruled strip, a closed one opened along a
// ruling), the fewest runs of consecutive triangles that each unfold without overlap, with
// the cuts moved so that the runs have similar areas: cut k goes where the area before it is
// nearest k/m of the total, within the range that leaves the rest coverable by the runs left
// (overlap-freeness is inherited by sub-runs, so greedy runs from either end bound it).
// Empty when the triangles are not one path.
std::vector<std::vector<int>> balanced_runs(const RuledStrip& strip,
                                            const std::vector<std::array<int, 3>>& neighbour,
                                            const std::vector<int>& order,
                                            const std::vector<bool>& usable, double cell_size,
                                            double tolerance) {
  const int n = static_cast<int>(order.size());
  if (n < 2) return {};
  if (static_cast<int>(std::count(usable.begin(), usable.end(), true)) != n) return {};
  for (int k = 1; k < n; ++k) {
    const auto& links = neighbour[order[k]];
    if (std::find(links.begin(), links.end(), order[k - 1]) == links.end()) return {};
  }
  auto run_of = [&](int begin, int end, bool reverse) {
    std::vector<int> run(order.begin() + begin, order.begin() + end);
    if (reverse) std::reverse(run.begin(), run.end());
    return run;
  };
  // How far an overlap-free run reaches from `begin` forwards (its end), or from `end`
  // backwards (its begin).
  auto forward = [&](int begin) {
    FlatBuilder builder{FlatStrip{}, TriangleGrid2(cell_size)};
    return begin + static_cast<int>(
                       place_run(strip, neighbour, run_of(begin, n, false), builder, tolerance));
  };
  auto backward = [&](int end) {
    FlatBuilder builder{FlatStrip{}, TriangleGrid2(cell_size)};
    return end -
           static_cast<int>(place_run(strip, neighbour, run_of(0, end, true), builder, tolerance));
  };
  int runs = 0;
  for (int begin = 0; begin < n; begin = forward(begin)) ++runs;
  if (runs < 2) return {};
  // latest[r]: the earliest triangle from which r runs still reach the end.
  std::vector<int> latest(runs, n);
  for (int r = 1; r < runs; ++r) latest[r] = backward(latest[r - 1]);
  std::vector<double> area(n + 1, 0.0);
  for (int k = 0; k < n; ++k) {
    const Triangle& t = strip.mesh.triangles[order[k]];
    const auto& v = strip.mesh.vertices;
    area[k + 1] = area[k] + 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm();
  }
  std::vector<std::vector<int>> result;
  int begin = 0;
  for (int left = runs; left > 1; --left) {
    const int hi = forward(begin);
    const int lo = std::max(begin + 1, latest[left - 1]);
    const double target = area[begin] + (area[n] - area[begin]) / left;
    int best = std::clamp(hi, lo, hi);
    for (int end = lo; end <= hi; ++end)
      if (std::abs(area[end] - target) < std::abs(area[best] - target)) best = end;
    result.push_back(run_of(begin, best, false));
    begin = best;
  }
  result.push_back(run_of(begin, n, false));
  return result;
}

// Whether snapping each point v of `flat` onto remap[v] keeps its edges' lengths
// (weld_keeps_lengths): a strip that lies flat but for rounding (a cap whose apex is a hair
// off its plane) closes with a gap a weld would pour into the edges beside it.
bool remap_keeps_lengths(const FlatStrip& flat, const std::vector<int>& remap) {
  std::vector<Vec2> after(remap.size());
  for (std::size_t v = 0; v < remap.size(); ++v) after[v] = flat.vertices2d[remap[v]];
  return weld_keeps_lengths(flat.vertices3d, flat.triangles, flat.vertices2d, after);
}

// Where both copies of each end of the opened ruling (3D points p and q) lie within `reach` of
// each other on paper, the later copies become the earlier ones (and are dropped).
void weld_flat_ruling(FlatStrip& flat, const Vec3& p, const Vec3& q, double reach) {
  std::vector<int> remap(flat.vertices3d.size());
  for (std::size_t v = 0; v < remap.size(); ++v) remap[v] = static_cast<int>(v);
  for (const Vec3* end : {&p, &q}) {
    std::vector<int> copies;
    for (std::size_t v = 0; v < flat.vertices3d.size(); ++v)
      if (flat.vertices3d[v] == *end) copies.push_back(static_cast<int>(v));
    if (copies.size() == 1) continue;  // a cone's apex: placed once
    if (copies.size() != 2) return;
    if ((flat.vertices2d[copies[0]] - flat.vertices2d[copies[1]]).norm() > reach) return;
    remap[copies[1]] = copies[0];
  }
  bool welds = false;
  for (std::size_t v = 0; v < remap.size(); ++v) welds = welds || remap[v] != static_cast<int>(v);
  if (!welds) return;
  if (!remap_keeps_lengths(flat, remap)) return;
  std::vector<int> index(remap.size(), -1);
  FlatStrip welded;
  for (std::size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] != static_cast<int>(v)) continue;
    index[v] = static_cast<int>(welded.vertices3d.size());
    welded.vertices3d.push_back(flat.vertices3d[v]);
    welded.vertices2d.push_back(flat.vertices2d[v]);
    if (!flat.uvs.empty()) welded.uvs.push_back(flat.uvs[v]);
  }
  for (Triangle t : flat.triangles) {
    for (int& v : t) v = index[remap[v]];
    welded.triangles.push_back(t);
  }
  flat = std::move(welded);
}

// A triangle with two corners at one 3D point (a fan whose apex lies on its own polyline, as
// when a flat disc is fanned from a corner; two polylines sharing an end) has no area. Its two
// copies of the point become one and the triangle goes: left in, it would print as a piece of
// no area (a cut line with a tab on each side) wherever the layout splits the strip, and as a
// zero-length cut edge. Copies are joined only where they also lie together on paper (within
// `reach`) and share their texture coordinates.
void weld_repeated_points(FlatStrip& flat, double reach) {
  UnionFind same(flat.vertices3d.size());
  bool any = false;
  for (const Triangle& t : flat.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      if (a == b || flat.vertices3d[a] != flat.vertices3d[b]) continue;
      if ((flat.vertices2d[a] - flat.vertices2d[b]).norm() > reach) continue;
      if (!flat.uvs.empty() && flat.uvs[a] != flat.uvs[b]) continue;
      same.unite(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
      any = true;
    }
  if (!any) return;
  std::vector<int> remap(flat.vertices3d.size());
  for (std::size_t v = 0; v < remap.size(); ++v) remap[v] = static_cast<int>(same.find(v));
  if (!remap_keeps_lengths(flat, remap)) return;
  std::vector<int> index(flat.vertices3d.size(), -1);
  FlatStrip welded;
  welded.id = flat.id;
  welded.source_strip = flat.source_strip;
  for (std::size_t v = 0; v < index.size(); ++v) {
    if (same.find(v) != v) continue;
    index[v] = static_cast<int>(welded.vertices3d.size());
    welded.vertices3d.push_back(flat.vertices3d[v]);
    welded.vertices2d.push_back(flat.vertices2d[v]);
    if (!flat.uvs.empty()) welded.uvs.push_back(flat.uvs[v]);
  }
  for (Triangle t : flat.triangles) {
    for (int& v : t) v = index[same.find(static_cast<std::size_t>(v))];
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) welded.triangles.push_back(t);
  }
  if (welded.triangles.empty()) return;  // nothing but such triangles: left as it is
  flat = std::move(welded);
}

// The strip's dual graph: which triangles are usable (three distinct corners), the triangle
// across each edge, and for a closed strip the shortest ruling it is opened along (its dual
// link cut); with the sum and count of the usable triangles' edge lengths.
struct StripDual {
  std::vector<bool> usable;
  std::vector<std::array<int, 3>> neighbour;  // neighbour[t][i]: across edge (t[i], t[i+1])
  std::pair<int, int> opened{-1, -1};         // the ruling a closed strip is opened along
  double edge_length_sum = 0.0;
  int edge_count = 0;
};

StripDual strip_dual(const RuledStrip& strip, const UnfoldOptions& options) {
  const auto& vertices = strip.mesh.vertices;
  const auto& triangles = strip.mesh.triangles;
  const int triangle_count = static_cast<int>(triangles.size());
  StripDual dual;
  std::vector<bool>& usable = dual.usable;
  usable.resize(triangle_count);
  for (int t = 0; t < triangle_count; ++t) {
    const Triangle& tri = triangles[t];
    usable[t] = tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0];
  }

  // Dual graph: neighbour[t][i] is the triangle across edge (t[i], t[i+1]).
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edge_faces;
  double& edge_length_sum = dual.edge_length_sum;
  int& edge_count = dual.edge_count;
  for (int t = 0; t < triangle_count; ++t) {
    if (!usable[t]) continue;
    for (int i = 0; i < 3; ++i) {
      int u = triangles[t][i], v = triangles[t][(i + 1) % 3];
      edge_faces[{std::min(u, v), std::max(u, v)}].push_back({t, i});
      edge_length_sum += (vertices[v] - vertices[u]).norm();
      ++edge_count;
    }
  }
  std::vector<std::array<int, 3>>& neighbour = dual.neighbour;
  neighbour.assign(triangle_count, {-1, -1, -1});
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
  std::pair<int, int>& opened = dual.opened;
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
      opened = {u, v};
      break;
    }
  }
  return dual;
}

}  // namespace

std::vector<FlatStrip> unfold_strip(const RuledStrip& strip, int source_strip_id, int first_flat_id,
                                    const UnfoldOptions& options) {
  validate(strip, options);
  const auto& vertices = strip.mesh.vertices;
  const auto& triangles = strip.mesh.triangles;
  const int triangle_count = static_cast<int>(triangles.size());

  StripDual dual = strip_dual(strip, options);
  const std::vector<bool>& usable = dual.usable;
  std::vector<std::array<int, 3>>& neighbour = dual.neighbour;
  const std::pair<int, int> opened = dual.opened;
  const double edge_length_sum = dual.edge_length_sum;
  const int edge_count = dual.edge_count;

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
  std::vector<int> visit_order;  // triangles in the order they were placed
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
    visit_order.push_back(root);
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
        visit_order.push_back(t);
      }
    }
  }

  // A strip that had to be split where it first overlapped itself: split it again into as
  // many pieces, but of similar area, so that no piece is a sliver at the end.
  if (builders.size() > 1) {
    std::vector<std::vector<int>> runs =
        balanced_runs(strip, neighbour, visit_order, usable, cell_size, tolerance);
    if (!runs.empty()) {
      builders.clear();
      for (const std::vector<int>& run : runs) {
        FlatBuilder builder{FlatStrip{}, TriangleGrid2(cell_size)};
        place_run(strip, neighbour, run, builder, tolerance);
        builders.push_back(std::move(builder));
      }
    }
  }

  // A closed strip that lies flat (a disc fanned from a point in its plane, a flat ring)
  // closes up on paper: its opened ruling lands on itself, and welding it leaves no slit.
  if (builders.size() == 1 && opened.first >= 0)
    weld_flat_ruling(builders.front().flat, vertices[opened.first], vertices[opened.second],
                     options.flat_close_tolerance * mean_edge);

  std::vector<FlatStrip> result;
  result.reserve(builders.size());
  for (std::size_t k = 0; k < builders.size(); ++k) {
    FlatStrip& flat = builders[k].flat;
    flat.id = first_flat_id + static_cast<int>(k);
    flat.source_strip = source_strip_id;
    weld_repeated_points(flat, kRepeatedPointReach * mean_edge);
    flat.boundary = flat_boundary(flat.triangles);
    result.push_back(std::move(flat));
  }
  return result;
}

}  // namespace papercraft
