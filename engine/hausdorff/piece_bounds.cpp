// Upper bounds of the distance from a source piece to the target (piece_bounds.h).
#include "engine/hausdorff/piece_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace papercraft::hausdorff_internal {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The Voronoi partition of a triangle by its corners: point slots 0-2 corners, 3-5 edge
// midpoints (m01, m12, m20), 6-7 inner points (circumcentre, or where the bisectors of the
// short edges cross the longest edge of an obtuse triangle).
struct VoronoiRegions {
  std::array<Vec3, 8> points;
  std::array<std::array<int, 5>, 3> vertices;  // slots of each region's polygon
  std::array<int, 3> vertex_count;
  std::array<double, 3> radius;  // max distance from corner i over its region
};

VoronoiRegions voronoi_regions(const Vec3& v0, const Vec3& v1, const Vec3& v2) {
  VoronoiRegions r;
  r.points[0] = v0;
  r.points[1] = v1;
  r.points[2] = v2;
  r.points[3] = 0.5 * (v0 + v1);
  r.points[4] = 0.5 * (v1 + v2);
  r.points[5] = 0.5 * (v2 + v0);
  const std::array<double, 3> length2 = {(v1 - v0).squaredNorm(), (v2 - v1).squaredNorm(),
                                         (v0 - v2).squaredNorm()};
  // Longest edge (ia, ib) with opposite corner ic; midpoint slot of edge k is 3 + k.
  int longest = 0;
  if (length2[1] > length2[longest]) longest = 1;
  if (length2[2] > length2[longest]) longest = 2;
  const int ia = longest, ib = (longest + 1) % 3, ic = (longest + 2) % 3;
  const Vec3& a = r.points[ia];
  const Vec3& b = r.points[ib];
  const Vec3& c = r.points[ic];
  const int mid_ab = 3 + ia, mid_bc = 3 + ib, mid_ca = 3 + ic;
  const Vec3 ca = a - c, cb = b - c;
  if (ca.dot(cb) > 0.0) {
    // Acute: the circumcentre lies inside and all three regions meet there. The angle at c
    // is the largest and at least 60 degrees, so |ca x cb| is well away from zero.
    const Vec3 n = ca.cross(cb);
    r.points[6] =
        c + (ca.squaredNorm() * cb - cb.squaredNorm() * ca).cross(n) / (2.0 * n.squaredNorm());
    r.points[7] = r.points[6];
    r.vertices[ia] = {ia, mid_ab, 6, mid_ca, 0};
    r.vertices[ib] = {ib, mid_bc, 6, mid_ab, 0};
    r.vertices[ic] = {ic, mid_ca, 6, mid_bc, 0};
    r.vertex_count = {4, 4, 4};
  } else {
    // Right or obtuse at c (also every degenerate case): the bisector of ca meets ab at p,
    // that of cb at q, in the order a, p, q, b.
    const Vec3 ab = b - a;
    auto fraction = [](double numerator, double denominator) {
      return denominator > 0.0 ? std::clamp(numerator / (2.0 * denominator), 0.0, 1.0) : 0.0;
    };
    const double fp = fraction(ca.squaredNorm(), ab.dot(c - a));
    const double fq = fraction(cb.squaredNorm(), (-ab).dot(c - b));
    r.points[6] = a + fp * ab;
    r.points[7] = b - fq * ab;
    r.vertices[ia] = {ia, mid_ca, 6, 0, 0};
    r.vertices[ib] = {ib, mid_bc, 7, 0, 0};
    r.vertices[ic] = {ic, mid_ca, 6, 7, mid_bc};
    r.vertex_count[ia] = 3;
    r.vertex_count[ib] = 3;
    r.vertex_count[ic] = 5;
  }
  for (int i = 0; i < 3; ++i) {
    double radius2 = 0.0;
    for (int k = 1; k < r.vertex_count[i]; ++k) {
      radius2 = std::max(radius2, (r.points[r.vertices[i][k]] - r.points[i]).squaredNorm());
    }
    r.radius[i] = std::sqrt(radius2);
  }
  return r;
}

// Across each edge of the target: face_edge[3 t + k] for edge k (corner k -> k + 1) of
// triangle t is the one other triangle holding that edge in the opposite direction, when the
// edge is held by exactly these two (kOpen: by t alone; kIrregular: any other case). Lets the
// projection bound check a patch's consistency in linear time.
constexpr int kOpen = -1;
constexpr int kIrregular = -2;

}  // namespace

std::vector<int> edge_neighbours(const TriangleMesh& mesh) {
  const std::size_t vertex_count = mesh.vertices.size();
  const std::size_t edge_count = 3 * mesh.triangles.size();
  // Directed edges grouped by their first vertex (counting sort).
  std::vector<int> start(vertex_count + 1, 0);
  for (const Triangle& f : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++start[f[k] + 1];
  }
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<int> by_from(edge_count);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < edge_count; ++e) {
    by_from[fill[mesh.triangles[e / 3][e % 3]]++] = static_cast<int>(e);
  }
  auto head = [&](int e) { return mesh.triangles[e / 3][(e % 3 + 1) % 3]; };
  std::vector<int> neighbour(edge_count, kIrregular);
  for (std::size_t e = 0; e < edge_count; ++e) {
    const int from = mesh.triangles[e / 3][e % 3];
    const int to = head(static_cast<int>(e));
    int same = 0, opposite = 0, other = -1;
    for (int i = start[from]; i < start[from + 1]; ++i) same += head(by_from[i]) == to;
    for (int i = start[to]; i < start[to + 1]; ++i) {
      if (head(by_from[i]) == from) {
        ++opposite;
        other = by_from[i] / 3;
      }
    }
    if (same == 1 && opposite == 0) neighbour[e] = kOpen;
    if (same == 1 && opposite == 1) neighbour[e] = other;
  }
  return neighbour;
}

namespace {

// Projection bound for a piece T over a target patch that is a height field above T's plane
// (a coarse triangle over a fine surface: the strip -> part direction). P = target
// triangles near T facing T's normal (by at least kMinFacing). If P is consistently oriented
// (every edge shared by at most two of them, in opposite directions), the projection
// along T's normal is an open map on P minus its boundary edges; if moreover no boundary edge
// projects onto T and one point of T is covered, T lies inside the projection of P (T is
// connected). Every x of T then lies below or above some t of P, d(x, target) <= |lambda_t(x)|
// (the distance along the normal to t), which is affine on the convex cell T cap proj(t),
// so its maximum is at the cell's corners. Returns +infinity when a condition fails.
constexpr double kMinFacing = 0.05;
constexpr std::size_t kMaxPatch = 512;

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Conservative 2D test: false only if the closed segment [a, b] and the closed triangle
// (q0, q1, q2) are separated by more than margin along some axis.
bool segment_may_meet_triangle(const Vec2& a, const Vec2& b, const std::array<Vec2, 3>& q,
                               double margin) {
  auto separated = [&](const Vec2& axis) {
    const double length = axis.norm();
    if (length == 0.0) return false;
    double t_min = kInfinity, t_max = -kInfinity;
    for (const Vec2& v : q) {
      t_min = std::min(t_min, axis.dot(v));
      t_max = std::max(t_max, axis.dot(v));
    }
    const double s_min = std::min(axis.dot(a), axis.dot(b));
    const double s_max = std::max(axis.dot(a), axis.dot(b));
    return s_min > t_max + margin * length || s_max < t_min - margin * length;
  };
  for (int i = 0; i < 3; ++i) {
    const Vec2 edge = q[(i + 1) % 3] - q[i];
    if (separated(Vec2(-edge.y(), edge.x()))) return false;
  }
  const Vec2 direction = b - a;
  return !separated(Vec2(-direction.y(), direction.x()));
}

// The general consistency check of a patch of the target (where its edge neighbours do not
// decide): its edges sorted, every edge held by two patch triangles in opposite directions or
// by one, and then `boundary_meets_piece(from, to)` false; none held by three or more.
template <class BoundaryMeetsPiece>
bool patch_consistent(const TriangleMesh& mesh, const std::vector<int>& patch,
                      BoundaryMeetsPiece boundary_meets_piece) {
  // Edge (low, high) with its direction bit, sortable as one integer.
  thread_local std::vector<std::uint64_t> edges;
  edges.clear();
  for (int t : patch) {
    const Triangle& f = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const auto from = static_cast<std::uint64_t>(f[k]),
                 to = static_cast<std::uint64_t>(f[(k + 1) % 3]);
      edges.push_back(from < to ? (from << 33 | to << 1 | 1) : (to << 33 | from << 1));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    const std::uint64_t key = edges[i] >> 1;
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] >> 1 == key) ++j;
    if (j - i == 2) {
      if ((edges[i] & 1) == (edges[i + 1] & 1)) return false;  // same direction twice
    } else if (j - i == 1) {
      if (boundary_meets_piece(static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)))
        return false;
    } else {
      return false;  // an edge of three or more facing triangles
    }
    i = j;
  }
  return true;
}

double projection_upper_bound(const std::array<Corner, 3>& c, const TriangleBvh& target,
                              const std::vector<int>& neighbours, double threshold) {
  const Vec3& origin = c[0].point;
  const Vec3 edge1 = c[1].point - origin, edge2 = c[2].point - origin;
  const Vec3 normal = edge1.cross(edge2);
  const double size = std::max({edge1.norm(), edge2.norm(), (c[2].point - c[1].point).norm()});
  const double normal_length = normal.norm();
  if (!(normal_length > 1e-6 * size * size)) return kInfinity;
  const Vec3 n = normal / normal_length;
  const Vec3 u = edge1.normalized();
  const Vec3 v = n.cross(u);
  auto project = [&](const Vec3& x) { return Vec2((x - origin).dot(u), (x - origin).dot(v)); };
  const std::array<Vec2, 3> piece = {Vec2(0.0, 0.0), project(c[1].point), project(c[2].point)};
  // Projected coordinates carry rounding errors relative to the coordinates' magnitude.
  const double margin = 1e-10 * (size + origin.cwiseAbs().maxCoeff());

  const TriangleMesh& mesh = target.mesh();
  auto face_normal = [&](int t) {
    const Triangle& f = mesh.triangles[t];
    return Vec3((mesh.vertices[f[1]] - mesh.vertices[f[0]])
                    .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]));
  };
  // A corner usually lies over its nearest triangle t_i, where the bound is at least
  // d_i / cos(n, n_t_i): skip the work when that already exceeds the threshold.
  for (const Corner& corner : c) {
    const Vec3 nt = face_normal(corner.nearest);
    if (corner.distance * nt.norm() > threshold * std::abs(nt.dot(n))) return kInfinity;
  }

  // Only target triangles within `threshold` along the normal can give a bound below it.
  Aabb box;
  for (const Corner& corner : c) {
    box.extend(corner.point + threshold * n);
    box.extend(corner.point - threshold * n);
  }
  thread_local std::vector<int> nearby;
  thread_local std::vector<int> patch;
  nearby.clear();
  patch.clear();
  // A patch much larger than that costs more than the splits it would save.
  if (!target.triangles_meeting(box, nearby, kMaxPatch)) return kInfinity;

  const double side = face_normal(c[0].nearest).dot(n) >= 0.0 ? 1.0 : -1.0;
  for (int t : nearby) {
    const Vec3 nt = face_normal(t);
    if (side * nt.dot(n) > kMinFacing * nt.norm()) patch.push_back(t);
  }
  if (patch.empty()) return kInfinity;

  const Vec2 piece_min = piece[0].cwiseMin(piece[1]).cwiseMin(piece[2]).array() - margin;
  const Vec2 piece_max = piece[0].cwiseMax(piece[1]).cwiseMax(piece[2]).array() + margin;
  const Vec2 centroid = (piece[0] + piece[1] + piece[2]) / 3.0;
  bool seeded = false;
  double bound = 0.0;
  std::array<Vec2, 9> polygon, clipped;
  for (int t : patch) {
    const Triangle& f = mesh.triangles[t];
    const std::array<Vec3, 3> corners = {mesh.vertices[f[0]], mesh.vertices[f[1]],
                                         mesh.vertices[f[2]]};
    const std::array<Vec2, 3> image = {project(corners[0]), project(corners[1]),
                                       project(corners[2])};
    const Vec2 image_min = image[0].cwiseMin(image[1]).cwiseMin(image[2]);
    const Vec2 image_max = image[0].cwiseMax(image[1]).cwiseMax(image[2]);
    if ((image_min.array() > piece_max.array()).any() ||
        (image_max.array() < piece_min.array()).any()) {
      continue;
    }
    if (!seeded) {
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k) {
        const Vec2 edge = image[(k + 1) % 3] - image[k];
        inside = side * cross2(edge, centroid - image[k]) > margin * edge.norm();
      }
      seeded = inside;
    }
    // Sutherland-Hodgman: the piece clipped to the image of t.
    int count = 3;
    std::copy(piece.begin(), piece.end(), polygon.begin());
    for (int k = 0; k < 3 && count > 0; ++k) {
      const Vec2& a = image[k];
      const Vec2 edge = image[(k + 1) % 3] - a;
      int out = 0;
      for (int i = 0; i < count; ++i) {
        const Vec2& p = polygon[i];
        const Vec2& q = polygon[(i + 1) % count];
        const double sp = side * cross2(edge, p - a), sq = side * cross2(edge, q - a);
        if (sp >= 0.0) clipped[out++] = p;
        if ((sp >= 0.0) != (sq >= 0.0)) clipped[out++] = p + (q - p) * (sp / (sp - sq));
      }
      count = out;
      std::copy(clipped.begin(), clipped.begin() + count, polygon.begin());
    }
    const Vec3 nt = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    const double facing = nt.dot(n);
    for (int i = 0; i < count; ++i) {
      const Vec3 x = origin + polygon[i].x() * u + polygon[i].y() * v;
      bound = std::max(bound, std::abs(nt.dot(corners[0] - x) / facing));
    }
    // Not yet proven a bound (the topology checks come below): useless above the threshold.
    if (bound > threshold) return kInfinity;
  }
  if (!seeded) return kInfinity;

  // Consistency of the patch and its boundary edges. With the target's edge neighbours an
  // edge held by two triangles of the patch is an inner edge of consistent orientation, and
  // one held by a single patch triangle is a boundary edge of the patch, unless the target is
  // irregular there; then the general check below (sorting the patch's edges) decides.
  thread_local std::vector<std::uint32_t> mark;
  thread_local std::uint32_t generation = 0;
  if (mark.size() < mesh.triangles.size()) mark.resize(mesh.triangles.size(), 0);
  if (++generation == 0) {
    std::fill(mark.begin(), mark.end(), 0);
    generation = 1;
  }
  for (int t : patch) mark[t] = generation;
  auto boundary_meets_piece = [&](int from, int to) {
    const Vec2 a = project(mesh.vertices[from]);
    const Vec2 b = project(mesh.vertices[to]);
    return !(std::max(a.x(), b.x()) < piece_min.x() || std::min(a.x(), b.x()) > piece_max.x() ||
             std::max(a.y(), b.y()) < piece_min.y() || std::min(a.y(), b.y()) > piece_max.y()) &&
           segment_may_meet_triangle(a, b, piece, margin);
  };
  bool irregular = false;
  for (int t : patch) {
    const Triangle& f = mesh.triangles[t];
    for (int k = 0; k < 3 && !irregular; ++k) {
      const int other = neighbours[3 * static_cast<std::size_t>(t) + k];
      if (other == kIrregular) {
        irregular = true;
      } else if ((other == kOpen || mark[other] != generation) &&
                 boundary_meets_piece(f[k], f[(k + 1) % 3])) {
        return kInfinity;
      }
    }
    if (irregular) break;
  }
  if (!irregular) return bound;
  return patch_consistent(mesh, patch, boundary_meets_piece) ? bound : kInfinity;
}

}  // namespace

/// An upper bound of max_{x in piece} d(x, target): the cascade of the header comment,
/// stopping at the first bound <= threshold.
double piece_upper_bound(const std::array<Corner, 3>& c, const TriangleBvh& target,
                         const std::vector<int>& neighbours, double threshold) {
  const double corner_max = std::max({c[0].distance, c[1].distance, c[2].distance});
  if (c[0].nearest == c[1].nearest && c[1].nearest == c[2].nearest) return corner_max;

  const VoronoiRegions regions = voronoi_regions(c[0].point, c[1].point, c[2].point);
  double lipschitz = 0.0;
  for (int i = 0; i < 3; ++i) lipschitz = std::max(lipschitz, c[i].distance + regions.radius[i]);
  if (lipschitz <= threshold) return lipschitz;

  std::array<int, 3> candidates;
  int candidate_count = 0;
  for (int i = 0; i < 3; ++i) {
    if (std::find(candidates.begin(), candidates.begin() + candidate_count, c[i].nearest) ==
        candidates.begin() + candidate_count) {
      candidates[candidate_count++] = c[i].nearest;
    }
  }
  // distance[slot][candidate], computed on demand (negative: not yet).
  std::array<std::array<double, 3>, 8> distance;
  for (auto& row : distance) row.fill(-1.0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < candidate_count; ++j) {
      if (candidates[j] == c[i].nearest) distance[i][j] = c[i].distance;
    }
  }
  auto distance_to = [&](int slot, int j) {
    double& d = distance[slot][j];
    if (d < 0.0)
      d = std::sqrt(target.squared_distance_to_triangle(regions.points[slot], candidates[j]));
    return d;
  };

  // Convexity of d(., t) over the whole piece (Tang et al. 2009).
  double best = lipschitz;
  for (int j = 0; j < candidate_count; ++j) {
    double m = 0.0;
    for (int slot = 0; slot < 3 && m < best; ++slot) m = std::max(m, distance_to(slot, j));
    best = std::min(best, m);
  }
  if (best <= threshold) return best;

  // The same per Voronoi region, each also capped by its Lipschitz bound.
  double regional = 0.0;
  for (int i = 0; i < 3 && regional < best; ++i) {
    double region_bound = c[i].distance + regions.radius[i];
    for (int j = 0; j < candidate_count; ++j) {
      double m = 0.0;
      for (int k = 0; k < regions.vertex_count[i] && m < region_bound; ++k) {
        m = std::max(m, distance_to(regions.vertices[i][k], j));
      }
      region_bound = std::min(region_bound, m);
    }
    regional = std::max(regional, region_bound);
  }
  best = std::min(best, regional);
  if (best <= threshold) return best;
  // The projection bound costs a range query and a patch check, about what a dozen splits
  // cost: worth it only where the Lipschitz radius is large against the remaining slack.
  const double radius = std::max({regions.radius[0], regions.radius[1], regions.radius[2]});
  if (radius <= 2.0 * (threshold - corner_max)) return best;
  return std::min(best, projection_upper_bound(c, target, neighbours, threshold));
}

}  // namespace papercraft::hausdorff_internal
