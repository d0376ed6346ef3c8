#include "core/dual_cuts.h"

#include <algorithm>
#include <string>

#include "core/errors.h"

namespace papercraft {

DualCuts::DualCuts(int count, const std::vector<std::pair<int, int>>& inner)
    : inner_first_(inner.size()), cut_off_(inner.size(), -1) {
  if (count < 0) throw InvalidInputException("DualCuts: negative triangle count");
  std::vector<std::vector<std::pair<int, int>>> across(count);  // (triangle, inner edge)
  for (std::size_t e = 0; e < inner.size(); ++e) {
    const auto [a, b] = inner[e];
    if (a < 0 || a >= count || b < 0 || b >= count || a == b)
      throw InvalidInputException("DualCuts: inner edge " + std::to_string(e) +
                                  " joins triangles " + std::to_string(a) + " and " +
                                  std::to_string(b) + " of " + std::to_string(count));
    inner_first_[e] = a;
    across[a].emplace_back(b, static_cast<int>(e));
    across[b].emplace_back(a, static_cast<int>(e));
  }
  enter_.assign(count, -1);
  leave_.assign(count, 0);
  if (count == 0) return;
  // Iterative depth-first search from triangle 0. low[t]: the earliest entry time reached from
  // t's subtree by one arc that is not a tree arc; the tree arc into t is a bridge when that is
  // no earlier than t itself. The arc a triangle was entered by is skipped by its index, so a
  // second arc between the same two triangles counts as a cycle.
  std::vector<int> low(count, 0);
  struct Visit {
    int triangle, via, next;  // via: the inner edge it was entered by (-1 at the root)
  };
  std::vector<Visit> stack{{0, -1, 0}};
  int clock = 0;
  enter_[0] = low[0] = clock++;
  while (!stack.empty()) {
    Visit& top = stack.back();
    if (top.next < static_cast<int>(across[top.triangle].size())) {
      const auto [t, e] = across[top.triangle][top.next++];
      if (e == top.via) continue;
      if (enter_[t] >= 0) {
        low[top.triangle] = std::min(low[top.triangle], enter_[t]);
      } else {
        enter_[t] = low[t] = clock++;
        stack.push_back({t, e, 0});  // `top` is not used after this
      }
      continue;
    }
    const Visit done = top;
    stack.pop_back();
    leave_[done.triangle] = clock;
    if (stack.empty()) break;
    const int parent = stack.back().triangle;
    low[parent] = std::min(low[parent], low[done.triangle]);
    if (low[done.triangle] > enter_[parent]) cut_off_[done.via] = done.triangle;
  }
  connected_ = clock == count;
}

int DualCuts::first_side_size(std::size_t e) const {
  const int root = cut_off_[e];
  const int subtree = leave_[root] - enter_[root];
  return below(e, inner_first_[e]) ? subtree : static_cast<int>(enter_.size()) - subtree;
}

}  // namespace papercraft
