#pragma once
// The cuts of a connected triangle set across one inner edge: which inner edges cut it in
// exactly two (the bridges of its dual graph, whose nodes are the triangles and whose arcs
// are the inner edges) and which triangles lie on each side. One depth-first pass (Tarjan's
// bridges, 1974) answers every edge: linear in the triangles, where cutting each edge and
// collecting the parts is quadratic.
//
//   DualCuts cuts(count, inner);  // inner[e]: the two triangles edge e joins
//   if (cuts.splits(e)) side = cuts.on_first_side(e, t);

#include <cstddef>
#include <utility>
#include <vector>

namespace papercraft {

class DualCuts {
 public:
  /// `count` triangles joined by `inner` edges, each given as the two triangles it joins (two
  /// triangles may be joined by more than one edge).
  /// \throws InvalidInputException if count is negative or an index is out of range, or an
  ///   edge joins a triangle to itself.
  DualCuts(int count, const std::vector<std::pair<int, int>>& inner);

  /// Whether every triangle is reached from every other across inner edges (true for none).
  bool connected() const { return connected_; }

  /// Whether cutting inner edge `e` alone leaves exactly two parts: false where the edge lies
  /// on a cycle (around an inner vertex, or a handle) or where the set is not connected.
  bool splits(std::size_t e) const { return connected_ && cut_off_[e] >= 0; }

  /// With splits(e): whether triangle `t` lies on the side of the edge's first triangle.
  bool on_first_side(std::size_t e, int t) const {
    return below(e, t) == below(e, inner_first_[e]);
  }

  /// With splits(e): how many triangles lie on the side of the edge's first triangle.
  int first_side_size(std::size_t e) const;

 private:
  // Whether t lies in the subtree the bridge cuts off: its entry time in [enter, leave).
  bool below(std::size_t e, int t) const {
    const int root = cut_off_[e];
    return enter_[t] >= enter_[root] && enter_[t] < leave_[root];
  }

  bool connected_ = true;
  std::vector<int> inner_first_;
  std::vector<int> cut_off_;  // per inner edge: the triangle whose subtree it cuts off, or -1
  std::vector<int> enter_, leave_;
};

}  // namespace papercraft
