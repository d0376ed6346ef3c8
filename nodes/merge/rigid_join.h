#pragma once
// Joining two flat strips along shared chains: the best rigid motion of one onto the other's
// image of a chain, and the union welded where it overlaps nowhere.

#include <vector>

#include "core/strip.h"
#include "nodes/merge/chains.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

struct RigidMotion {
  double cos = 1.0, sin = 0.0;
  Vec2 translation = Vec2::Zero();
  Vec2 operator()(const Vec2& p) const {
    return Vec2(cos * p.x() - sin * p.y(), sin * p.x() + cos * p.y()) + translation;
  }
};

/// Best rotation + translation taking the points `from` onto `to` (2D Procrustes without
/// reflection; Umeyama 1991 restricted to det R = +1).
RigidMotion fit(const std::vector<Vec2>& from, const std::vector<Vec2>& to);

/// The farthest that `motion` leaves a point of Y's side of `chain` from its partner in X.
double chain_residual(const FlatStrip& x, const FlatStrip& y, const Chain& chain,
                      const RigidMotion& motion);

/// The mean length of the strip's triangle edges in the plane (0 without triangles).
double mean_edge_length(const FlatStrip& strip);

/// Y moved onto X along one of their chains and welded into `merged`, or false when no chain
/// gives a congruent, overlap-free union. The chains are tried the longest first as the one to
/// fit; every other chain that then lands on its partner is welded too, keeping the map from
/// Y's vertices to X's one-to-one. Without `with_boundary` the union's boundary is left empty
/// (a caller that tries many unions and keeps one finds the boundary of that one).
bool try_merge(const FlatStrip& x, const FlatStrip& y, std::vector<Chain> chains,
               const MergeOptions& options, FlatStrip& merged, bool with_boundary = true);

}  // namespace papercraft::merge_detail
