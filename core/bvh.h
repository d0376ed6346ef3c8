#pragma once
// An axis-aligned bounding box tree over the triangles of a TriangleMesh for exact
// point-to-surface distance queries (the Hausdorff stage, the error map error.ply).
//
// Example:
//   TriangleBvh bvh(mesh);
//   BvhClosestHit hit = bvh.closest(p);  // hit.distance, hit.triangle, hit.point

#include <array>
#include <limits>
#include <span>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

struct TriangleBvhOptions {
  /// Most triangles in a leaf; a leaf may hold more only where centroids coincide.
  int leaf_size = 4;
  /// Bins per axis of the binned surface area heuristic.
  int sah_bins = 16;
};

/// Result of a closest-point query.
struct BvhClosestHit {
  /// Distance from the query to `point`; +infinity when no triangle lies within the bound.
  double distance = std::numeric_limits<double>::infinity();
  /// Index into mesh().triangles, or -1 when no triangle lies within the bound.
  int triangle = -1;
  Vec3 point = Vec3::Zero();
  /// Weights of the triangle's corners giving `point`.
  Vec3 barycentric = Vec3::Zero();

  bool found() const { return triangle >= 0; }
};

/// Axis-aligned box {min, max}.
struct Aabb {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Vec3& p);
  void extend(const Aabb& box);
  /// Squared distance from p to the box (0 inside): a lower bound of the squared distance
  /// from p to anything inside the box.
  double squared_distance(const Vec3& p) const;
};

/// A subtree of a TriangleBvh: its box and the triangles below it, which are the consecutive
/// slots [first_slot, first_slot + slot_count) of the tree's leaf order.
struct BvhSubtree {
  Aabb box;
  int node = -1;  // internal node (has children), or -1 for a leaf or an empty subtree
  int first_slot = 0;
  int slot_count = 0;
};

/// Immutable AABB tree (binned SAH, flat depth-first node array) over a copy of a mesh.
/// Queries are const and safe to run concurrently. Degenerate triangles (zero area,
/// coincident corners) are valid and behave as the segments or points they are.
///
/// Ties: among triangles at exactly the same computed distance the lowest index is
/// returned, whatever the traversal order or hints, so results are deterministic.
class TriangleBvh {
 public:
  /// \pre mesh has at least one triangle, every index is in range, every used coordinate is
  /// finite. \throws InvalidInputException otherwise.
  explicit TriangleBvh(const TriangleMesh& mesh, const TriangleBvhOptions& options = {});
  explicit TriangleBvh(TriangleMesh&& mesh, const TriangleBvhOptions& options = {});

  /// The indexed mesh the tree was built over (a copy).
  const TriangleMesh& mesh() const { return mesh_; }
  /// Bounding box of all triangles.
  const Aabb& bounds() const { return bounds_; }
  std::size_t node_count() const { return nodes_.size(); }

  /// The nearest point of the surface to p. Only triangles at distance <= upper_bound are
  /// considered (a known bound prunes the search); when none is, returns a hit with
  /// found() == false.
  BvhClosestHit closest(const Vec3& p,
                        double upper_bound = std::numeric_limits<double>::infinity()) const;

  /// closest(p) warm-started by candidate triangles likely to be near p (e.g. the nearest
  /// triangles of neighbouring points). The result does not depend on the candidates.
  /// \pre every candidate is a valid triangle index.
  BvhClosestHit closest(const Vec3& p, std::span<const int> candidate_triangles) const;

  /// closest(p) for each point, in parallel (oneTBB).
  std::vector<BvhClosestHit> closest(const std::vector<Vec3>& points) const;

  /// Appends to `out` the index of every triangle whose bounding box meets `box` (closed).
  void triangles_meeting(const Aabb& box, std::vector<int>& out) const;
  /// The same, giving up once more than `limit` triangles were appended (returns false; `out`
  /// then holds an incomplete list). Returns true when the list is complete.
  bool triangles_meeting(const Aabb& box, std::vector<int>& out, std::size_t limit) const;

  /// The whole tree as a subtree, for top-down walks (e.g. bounding a function over groups of
  /// triangles before looking at single ones).
  BvhSubtree root() const;
  /// The two subtrees below an internal one (subtree.node >= 0); an empty one has
  /// slot_count == 0.
  std::array<BvhSubtree, 2> children(const BvhSubtree& subtree) const;
  /// The mesh triangle at a slot of the leaf order. \pre 0 <= slot < triangle count.
  int triangle_at_slot(int slot) const { return packed_[slot].id; }

  /// Squared distance from p to triangle t of mesh(). \pre 0 <= t < triangle count.
  double squared_distance_to_triangle(const Vec3& p, int t) const;

 private:
  // Both children's boxes live in the parent, so one cache line pair decides both.
  // Child k: count[k] > 0: a leaf of count[k] triangles from slot child[k]; count[k] == 0:
  // the internal node child[k]; child[k] < 0: none (empty box).
  struct Node {
    std::array<double, 3> min[2];
    std::array<double, 3> max[2];
    int child[2];
    int count[2];
  };
  struct PackedTriangle {
    Vec3 a, b, c;
    int id;
    bool regular;
  };

  void build(const TriangleBvhOptions& options);
  void visit_triangle(const Vec3& p, int slot, double& best_squared, BvhClosestHit& best) const;
  void traverse(const Vec3& p, double& best_squared, BvhClosestHit& best) const;

  TriangleMesh mesh_;
  Aabb bounds_;
  std::vector<Node> nodes_;
  // Triangles in leaf order; slot_of_triangle_[t] is the slot of mesh triangle t.
  std::vector<PackedTriangle> packed_;
  std::vector<int> slot_of_triangle_;
  // Slots below each internal node: {first, count}.
  std::vector<std::array<int, 2>> node_slots_;
};

}  // namespace papercraft
