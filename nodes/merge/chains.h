#pragma once
// The shared boundaries of flat strips: chains of boundary edges that two strips glue with
// opposite directions (the same 3D end points, compared exactly as label_seams does), the
// single edges of those chains as hinges, and the strips beside a strip.

#include <array>
#include <functional>
#include <set>
#include <vector>

#include "core/strip.h"

namespace papercraft::merge_detail {

/// A shared boundary of strips X and Y: x[i] in X and y[i] in Y are the same 3D point.
struct Chain {
  std::vector<int> x;
  std::vector<int> y;
  double length = 0.0;
};

/// Two strips that share boundary chains, and the chains' total length.
struct PairCandidate {
  int x = -1;  // strip indices, x < y
  int y = -1;
  std::vector<Chain> chains;
  double total_length = 0.0;
};

/// The 3D segment p-q as a key, the same whichever way round it is given.
std::array<double, 6> exact_key(const Vec3& p, const Vec3& q);

/// The 3D edges (exact_key) of a strip's boundary.
std::set<std::array<double, 6>> rim_of(const FlatStrip& strip);

/// Chains of boundary edges glued (opposite directions) between every pair of strips, or,
/// given `with`, only the pairs strips[with] is in (the same pairs, in the same order, as the
/// whole list has; the edges of the others are looked at only where they lie on its rim).
/// The pairs with the longest total shared length come first.
std::vector<PairCandidate> shared_boundaries(const std::vector<FlatStrip>& strips, int with = -1);

/// A single-edge hinge: (pair index, edge) over shared_boundaries(strips), and whether the
/// edge is at an end of an open chain (the chain's other edges then all lie on one side of it).
struct Hinge {
  int pair;
  Chain edge;
  bool chain_end = false;
};

/// The single-edge hinges of the pairs `wanted` picks, the longest first.
std::vector<Hinge> hinges_of(const std::vector<PairCandidate>& pairs,
                             const std::vector<FlatStrip>& strips,
                             const std::function<bool(const PairCandidate&)>& wanted);

/// The indices of the strips with a boundary edge on strip `index`'s rim (its neighbours), in
/// order.
std::vector<int> strips_beside(const std::vector<FlatStrip>& strips, int index);

}  // namespace papercraft::merge_detail
