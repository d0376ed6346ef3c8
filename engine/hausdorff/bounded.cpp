#include "engine/hausdorff/bounded.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/errors.h"
#include "engine/hausdorff/piece_bounds.h"

namespace papercraft {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using hausdorff_internal::Corner;
using hausdorff_internal::edge_neighbours;
using hausdorff_internal::piece_upper_bound;

struct Piece {
  std::array<Corner, 3> corners;
  double upper;
  int side;
  int source_triangle;
  int depth;
};

// Max-queue of pieces by upper bound. The heap holds (upper, slot) pairs so that sifting
// moves 16 bytes rather than whole pieces.
class PieceQueue {
 public:
  bool empty() const { return heap_.empty(); }
  double top_upper() const { return heap_.front().upper; }

  void push(const Piece& piece) {
    int slot;
    if (free_.empty()) {
      slot = static_cast<int>(pieces_.size());
      pieces_.push_back(piece);
    } else {
      slot = free_.back();
      free_.pop_back();
      pieces_[slot] = piece;
    }
    heap_.push_back({piece.upper, slot});
    std::push_heap(heap_.begin(), heap_.end());
  }

  Piece pop() {
    std::pop_heap(heap_.begin(), heap_.end());
    const int slot = heap_.back().slot;
    heap_.pop_back();
    free_.push_back(slot);
    return pieces_[slot];
  }

 private:
  struct Entry {
    double upper;
    int slot;
    bool operator<(const Entry& other) const { return upper < other.upper; }
  };
  std::vector<Entry> heap_;
  std::vector<Piece> pieces_;
  std::vector<int> free_;
};

/// One direction of the distance: pieces of `source` measured against `target`.
struct Direction {
  const TriangleMesh* source;
  const TriangleBvh* target;
  const TriangleBvh* source_tree = nullptr;  // over *source when one exists
};

// Subtrees of the source tree with at most this many triangles are not bounded as a whole:
// their triangles go to the per-triangle bounds directly.
constexpr int kSmallSubtree = 8;

void validate_mesh(const TriangleMesh& mesh, const char* name) {
  if (mesh.triangles.empty()) {
    throw InvalidInputException(std::string("Hausdorff distance: mesh ") + name +
                                " has no triangles");
  }
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (int v : mesh.triangles[f]) {
      if (v < 0 || v >= vertex_count) {
        throw InvalidInputException(std::string("Hausdorff distance: triangle ") +
                                    std::to_string(f) + " of mesh " + name + " refers to vertex " +
                                    std::to_string(v) + " of " + std::to_string(vertex_count));
      }
      if (!mesh.vertices[v].allFinite()) {
        throw InvalidInputException(std::string("Hausdorff distance: vertex ") + std::to_string(v) +
                                    " of mesh " + name + " has a non-finite coordinate");
      }
    }
  }
}

enum class Mode { decision, value };

class BranchAndBound {
 public:
  BranchAndBound(std::vector<Direction> directions, Mode mode, double tolerance,
                 const BoundedHausdorffOptions& options)
      : directions_(std::move(directions)), mode_(mode), tolerance_(tolerance), options_(options) {}

  HausdorffResult run();

 private:
  double threshold() const;
  bool rejected() const { return mode_ == Mode::decision && lower_ > tolerance_; }
  void offer_lower(const Corner& corner, int side, int source_triangle);
  // Bounds whole subtrees of the source trees by one corner's distance plus the farthest
  // point of the subtree's box from it (d(., B) is 1-Lipschitz); marks the triangles of the
  // subtrees that this does not settle as active.
  // With stop_at_reject, returns as soon as a corner is farther than tau.
  void cull_subtrees(bool stop_at_reject);
  void evaluate_vertices();
  // Splits `piece` into children with bounds for `threshold`; returns the queries made.
  std::size_t split(const Piece& piece, double threshold, std::vector<Piece>& children) const;
  Corner query(int side, const Vec3& point, std::span<const int> candidates) const;

  std::vector<Direction> directions_;
  Mode mode_;
  double tolerance_;  // tau (decision) or the error bound (value)
  BoundedHausdorffOptions options_;

  std::vector<std::vector<Corner>> vertex_corners_;  // per direction, per source vertex
  std::vector<std::vector<int>> neighbours_;         // per direction, edge_neighbours(target)
  std::vector<std::vector<char>> active_;  // per direction, per source triangle: not settled yet
  PieceQueue queue_;
  double lower_ = 0.0;
  HausdorffWitness witness_;
  double settled_upper_ = 0.0;  // max upper bound of pieces dropped as settled
  std::size_t evaluations_ = 0;
};

double BranchAndBound::threshold() const {
  if (mode_ == Mode::value) return lower_ + tolerance_;
  if (lower_ <= tolerance_) return tolerance_;
  return lower_ + options_.precision * tolerance_;
}

void BranchAndBound::offer_lower(const Corner& corner, int side, int source_triangle) {
  if (corner.distance > lower_ || witness_.triangle < 0) {
    lower_ = std::max(lower_, corner.distance);
    witness_ = {corner.point, side, source_triangle, corner.distance};
  }
}

Corner BranchAndBound::query(int side, const Vec3& point, std::span<const int> candidates) const {
  const BvhClosestHit hit = directions_[side].target->closest(point, candidates);
  return {point, hit.distance, hit.triangle};
}

void BranchAndBound::cull_subtrees(bool stop_at_reject) {
  active_.resize(directions_.size());
  for (std::size_t side = 0; side < directions_.size(); ++side) {
    const TriangleMesh& source = *directions_[side].source;
    const TriangleBvh* tree = directions_[side].source_tree;
    std::vector<char>& active = active_[side];
    if (!tree) {
      active.assign(source.triangles.size(), 1);
      continue;
    }
    active.assign(source.triangles.size(), 0);
    // Level by level, so that the result does not depend on the thread count.
    std::vector<BvhSubtree> level = {tree->root()}, next;
    std::vector<Corner> probes;
    while (!level.empty()) {
      probes.assign(level.size(), Corner{Vec3::Zero(), 0.0, -1});
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, level.size(), 16),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t i = range.begin(); i != range.end(); ++i) {
                            if (level[i].slot_count <= kSmallSubtree) continue;
                            const int t = tree->triangle_at_slot(level[i].first_slot);
                            probes[i] = query(static_cast<int>(side),
                                              source.vertices[source.triangles[t][0]], {});
                          }
                        });
      for (std::size_t i = 0; i < level.size(); ++i) {
        const BvhSubtree& subtree = level[i];
        if (subtree.slot_count <= kSmallSubtree) {
          for (int s = subtree.first_slot; s < subtree.first_slot + subtree.slot_count; ++s) {
            active[tree->triangle_at_slot(s)] = 1;
          }
          continue;
        }
        ++evaluations_;
        offer_lower(probes[i], static_cast<int>(side), tree->triangle_at_slot(subtree.first_slot));
      }
      if (stop_at_reject && rejected()) return;
      const double level_threshold = threshold();
      next.clear();
      for (std::size_t i = 0; i < level.size(); ++i) {
        const BvhSubtree& subtree = level[i];
        if (subtree.slot_count <= kSmallSubtree) continue;
        const Vec3& p = probes[i].point;
        const Vec3 far =
            (p - subtree.box.min).cwiseAbs().cwiseMax((subtree.box.max - p).cwiseAbs());
        const double bound = probes[i].distance + far.norm();
        if (bound <= level_threshold) {
          settled_upper_ = std::max(settled_upper_, bound);
          continue;
        }
        for (const BvhSubtree& child : tree->children(subtree)) {
          if (child.slot_count > 0) next.push_back(child);
        }
      }
      level.swap(next);
    }
  }
}

void BranchAndBound::evaluate_vertices() {
  vertex_corners_.resize(directions_.size());
  for (std::size_t side = 0; side < directions_.size(); ++side) {
    const TriangleMesh& source = *directions_[side].source;
    std::vector<char> used(source.vertices.size(), 0);
    for (std::size_t f = 0; f < source.triangles.size(); ++f) {
      if (!active_[side][f]) continue;
      for (int v : source.triangles[f]) used[v] = 1;
    }
    std::vector<Corner>& corners = vertex_corners_[side];
    corners.assign(source.vertices.size(), Corner{Vec3::Zero(), 0.0, -1});
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, source.vertices.size(), 128),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        int previous = -1;
                        for (std::size_t v = range.begin(); v != range.end(); ++v) {
                          if (!used[v]) continue;
                          corners[v] = query(static_cast<int>(side), source.vertices[v],
                                             previous >= 0 ? std::span<const int>(&previous, 1)
                                                           : std::span<const int>());
                          previous = corners[v].nearest;
                        }
                      });
    for (std::size_t f = 0; f < source.triangles.size(); ++f) {
      if (!active_[side][f]) continue;
      for (int v : source.triangles[f]) {
        offer_lower(corners[v], static_cast<int>(side), static_cast<int>(f));
      }
    }
    evaluations_ += static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  }
}

std::size_t BranchAndBound::split(const Piece& piece, double threshold,
                                  std::vector<Piece>& children) const {
  const std::array<Corner, 3>& c = piece.corners;
  const TriangleBvh& target = *directions_[piece.side].target;
  const std::array<int, 3> candidates = {c[0].nearest, c[1].nearest, c[2].nearest};
  auto midpoint = [&](int i, int j) {
    return query(piece.side, 0.5 * (c[i].point + c[j].point), candidates);
  };
  auto add = [&](const Corner& x, const Corner& y, const Corner& z) {
    Piece child{{x, y, z}, 0.0, piece.side, piece.source_triangle, piece.depth + 1};
    child.upper = piece_upper_bound(child.corners, target, neighbours_[piece.side], threshold);
    children.push_back(child);
  };
  if (options_.split == PieceSplit::midpoints) {
    const Corner m01 = midpoint(0, 1), m12 = midpoint(1, 2), m20 = midpoint(2, 0);
    add(c[0], m01, m20);
    add(m01, c[1], m12);
    add(m20, m12, c[2]);
    add(m01, m12, m20);
    return 3;
  }
  int longest = 0;
  double longest2 = -1.0;
  for (int i = 0; i < 3; ++i) {
    const double length2 = (c[(i + 1) % 3].point - c[i].point).squaredNorm();
    if (length2 > longest2) {
      longest2 = length2;
      longest = i;
    }
  }
  const int i = longest, j = (longest + 1) % 3, k = (longest + 2) % 3;
  const Corner m = midpoint(i, j);
  add(c[i], m, c[k]);
  add(m, c[j], c[k]);
  return 1;
}

HausdorffResult BranchAndBound::run() {
  neighbours_.resize(directions_.size());
  for (std::size_t side = 0; side < directions_.size(); ++side) {
    neighbours_[side] = edge_neighbours(directions_[side].target->mesh());
  }
  const bool stop_at_reject = mode_ == Mode::decision && !options_.locate_maximum;
  cull_subtrees(stop_at_reject);
  if (!(stop_at_reject && rejected())) evaluate_vertices();

  if (!(stop_at_reject && rejected())) {
    // Bounds of every input triangle, in parallel; then the undecided ones are queued.
    std::vector<Piece> pieces;
    for (std::size_t side = 0; side < directions_.size(); ++side) {
      const TriangleMesh& source = *directions_[side].source;
      const std::vector<Corner>& corners = vertex_corners_[side];
      for (std::size_t f = 0; f < source.triangles.size(); ++f) {
        if (!active_[side][f]) continue;
        const Triangle& t = source.triangles[f];
        pieces.push_back({{corners[t[0]], corners[t[1]], corners[t[2]]},
                          0.0,
                          static_cast<int>(side),
                          static_cast<int>(f),
                          0});
      }
    }
    const double initial_threshold = threshold();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pieces.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t p = range.begin(); p != range.end(); ++p) {
                          pieces[p].upper = piece_upper_bound(
                              pieces[p].corners, *directions_[pieces[p].side].target,
                              neighbours_[pieces[p].side], initial_threshold);
                        }
                      });
    for (Piece& piece : pieces) {
      if (piece.upper <= initial_threshold) {
        settled_upper_ = std::max(settled_upper_, piece.upper);
      } else {
        queue_.push(piece);
      }
    }
  }

  std::vector<Piece> batch;
  std::vector<std::vector<Piece>> children;
  std::vector<std::size_t> queries;
  while (!queue_.empty() && !(stop_at_reject && rejected())) {
    const double round_threshold = threshold();
    if (queue_.top_upper() <= round_threshold) break;
    if (evaluations_ >= options_.max_evaluations) break;
    batch.clear();
    while (!queue_.empty() && batch.size() < options_.batch_size &&
           queue_.top_upper() > round_threshold) {
      const Piece piece = queue_.pop();
      if (piece.depth >= options_.max_depth) {
        // Cannot be refined further: its bound stands as it is.
        settled_upper_ = std::max(settled_upper_, piece.upper);
      } else {
        batch.push_back(piece);
      }
    }
    children.resize(batch.size());
    queries.assign(batch.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 4),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t b = range.begin(); b != range.end(); ++b) {
                          children[b].clear();
                          queries[b] = split(batch[b], round_threshold, children[b]);
                        }
                      });
    for (std::size_t b = 0; b < batch.size(); ++b) {
      evaluations_ += queries[b];
      for (const Piece& child : children[b]) {
        for (const Corner& corner : child.corners) {
          offer_lower(corner, child.side, child.source_triangle);
        }
      }
    }
    const double new_threshold = threshold();
    for (std::size_t b = 0; b < batch.size(); ++b) {
      for (const Piece& child : children[b]) {
        if (child.upper <= new_threshold) {
          settled_upper_ = std::max(settled_upper_, child.upper);
        } else {
          queue_.push(child);
        }
      }
    }
  }

  HausdorffResult result;
  result.lower = lower_;
  result.upper = std::max({lower_, settled_upper_, queue_.empty() ? 0.0 : queue_.top_upper()});
  result.witness = witness_;
  result.evaluations = evaluations_;
  if (mode_ == Mode::decision) {
    result.within = !rejected() && result.upper <= tolerance_;
    result.certified = rejected() || result.within;
  } else {
    result.within = result.upper - result.lower <= tolerance_;
    result.certified = result.within;
  }
  return result;
}

void validate_parameter(double value, const char* name, bool allow_zero) {
  if (!std::isfinite(value) || value < 0.0 || (!allow_zero && value == 0.0)) {
    throw InvalidInputException(std::string("Hausdorff distance: ") + name + " must be " +
                                (allow_zero ? "finite and >= 0" : "finite and > 0") + ", got " +
                                std::to_string(value));
  }
}

void validate_options(const BoundedHausdorffOptions& options) {
  validate_parameter(options.precision, "precision", false);
  if (options.batch_size == 0) {
    throw InvalidInputException("Hausdorff distance: batch_size must be at least 1");
  }
}

HausdorffResult two_sided(const TriangleBvh& a, const TriangleBvh& b, Mode mode, double tolerance,
                          const BoundedHausdorffOptions& options) {
  validate_options(options);
  return BranchAndBound({{&a.mesh(), &b, &a}, {&b.mesh(), &a, &b}}, mode, tolerance, options).run();
}

HausdorffResult two_sided(const TriangleMesh& a, const TriangleMesh& b, Mode mode, double tolerance,
                          const BoundedHausdorffOptions& options) {
  validate_mesh(a, "a");
  validate_mesh(b, "b");
  std::optional<TriangleBvh> tree_a, tree_b;
  tbb::parallel_invoke([&] { tree_a.emplace(a); }, [&] { tree_b.emplace(b); });
  return two_sided(*tree_a, *tree_b, mode, tolerance, options);
}

HausdorffResult one_sided(const TriangleMesh& a, const TriangleBvh& b, Mode mode, double tolerance,
                          const BoundedHausdorffOptions& options) {
  validate_mesh(a, "a");
  validate_options(options);
  return BranchAndBound({{&a, &b}}, mode, tolerance, options).run();
}

}  // namespace

HausdorffResult certified_hausdorff_within(const TriangleMesh& a, const TriangleMesh& b, double tau,
                                           const BoundedHausdorffOptions& options) {
  validate_parameter(tau, "tau", false);
  return two_sided(a, b, Mode::decision, tau, options);
}

HausdorffResult certified_hausdorff_within(const TriangleBvh& a, const TriangleBvh& b, double tau,
                                           const BoundedHausdorffOptions& options) {
  validate_parameter(tau, "tau", false);
  return two_sided(a, b, Mode::decision, tau, options);
}

HausdorffResult certified_hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                             double error_bound,
                                             const BoundedHausdorffOptions& options) {
  validate_parameter(error_bound, "error_bound", false);
  return two_sided(a, b, Mode::value, error_bound, options);
}

HausdorffResult certified_hausdorff_distance(const TriangleBvh& a, const TriangleBvh& b,
                                             double error_bound,
                                             const BoundedHausdorffOptions& options) {
  validate_parameter(error_bound, "error_bound", false);
  return two_sided(a, b, Mode::value, error_bound, options);
}

HausdorffResult certified_one_sided_hausdorff_within(const TriangleMesh& a, const TriangleBvh& b,
                                                     double tau,
                                                     const BoundedHausdorffOptions& options) {
  validate_parameter(tau, "tau", false);
  return one_sided(a, b, Mode::decision, tau, options);
}

HausdorffResult certified_one_sided_hausdorff_distance(const TriangleMesh& a, const TriangleBvh& b,
                                                       double error_bound,
                                                       const BoundedHausdorffOptions& options) {
  validate_parameter(error_bound, "error_bound", false);
  return one_sided(a, b, Mode::value, error_bound, options);
}

}  // namespace papercraft
