#include "nodes/segment/strip_estimate.h"

#include <algorithm>
#include <exception>
#include <vector>

#include "nodes/cut/rejected.h"
#include "nodes/hausdorff/bounded.h"
#include "nodes/hausdorff/decision.h"
#include "nodes/ruled/twist_dp.h"
#include "nodes/select/geodesic.h"

namespace papercraft {
namespace {

// Mirrors cut.harmonic's max_depth.
constexpr int kMaxDepth = 64;

}  // namespace

int estimate_strips(const Mesh& root, double tolerance, int cap) {
  struct Item {
    Mesh part;
    int depth;
  };
  const RejectedCutOptions cut_defaults;  // cut.harmonic's defaults
  std::vector<Item> stack;
  stack.push_back({root, 0});
  int strips = 0;
  try {
    while (!stack.empty()) {
      Item item = std::move(stack.back());
      stack.pop_back();
      const Mesh& part = item.part;
      const BoundarySelection selection = select_geodesic(part);
      const Polyline a = selection_polyline(part, selection.first, selection.first_closed);
      const Polyline b = selection_polyline(part, selection.second, selection.second_closed);
      std::vector<std::vector<int>> holes;
      auto used = [&](const std::vector<int>& loop) {
        auto chosen = [&](const std::vector<int>& side, bool closed) {
          return closed && std::find(side.begin(), side.end(), loop.front()) != side.end();
        };
        return chosen(selection.first, selection.first_closed) ||
               chosen(selection.second, selection.second_closed);
      };
      for (auto& loop : boundary_loops(part))
        if (!used(loop)) holes.push_back(std::move(loop));
      const RuledStrip strip = twist_minimizing_strip(a, b);
      const StripVerdict verdict =
          judge_strip(part, strip, static_cast<int>(holes.size()), tolerance,
                      [](const TriangleMesh& x, const TriangleMesh& y, double tau) {
                        return certified_hausdorff_within(x, y, tau, BoundedHausdorffOptions{});
                      });
      if (verdict.accept) {
        if (++strips > cap) return cap + 1;
        continue;
      }
      if (item.depth >= kMaxDepth) return cap + 1;
      WitnessCut cut = cut_rejected_part(
          part, selection.first, selection.first_closed, selection.second, selection.second_closed,
          verdict.hole >= 0 ? &holes[verdict.hole] : nullptr, verdict.witness, tolerance,
          cut_defaults);
      if (cut.pieces.empty()) return cap + 1;
      // Every piece makes at least one strip.
      if (strips + static_cast<int>(stack.size() + cut.pieces.size()) > cap) return cap + 1;
      for (Mesh& piece : cut.pieces) stack.push_back({std::move(piece), item.depth + 1});
    }
  } catch (const std::exception&) {
    return cap + 1;
  }
  return strips;
}

}  // namespace papercraft
