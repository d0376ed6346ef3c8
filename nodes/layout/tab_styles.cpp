// Tab styles: which side of each seam takes the flaps TabPlanner plans.
#include "nodes/layout/tab_styles.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "nodes/layout/tabs.h"

namespace papercraft::layout_internal {
namespace {

using ChainKey = std::tuple<int, int, int, int>;

ChainKey chain_key(const Chain& c, const std::vector<Piece>& pieces,
                   const std::vector<StripData>& strips) {
  const Piece& piece = pieces[c.piece];
  return {strips[piece.strip].strip->id, piece.index, c.loop, c.start};
}

// Positions (0 .. chain.count - 1) of `chain` that `parts`, runs of it, hold.
std::vector<char> positions_of(const Chain& chain, const Piece& piece,
                               const std::vector<Chain>& parts) {
  const int n = static_cast<int>(piece.loops[chain.loop].size());
  std::vector<char> along(chain.count, 0);
  for (const Chain& part : parts)
    for (int k = 0; k < part.count; ++k) {
      const int position = (part.start - chain.start + n + k) % n;
      if (position < chain.count) along[position] = 1;
    }
  return along;
}

// The runs of consecutive marked positions of `chain` as chains of their own.
std::vector<Chain> marked_parts(const Chain& chain, const Piece& piece,
                                const std::vector<char>& along) {
  const int n = static_cast<int>(piece.loops[chain.loop].size());
  std::vector<Chain> parts;
  for (int i = 0; i < chain.count; ++i) {
    if (!along[i] || (i > 0 && along[i - 1])) continue;
    int count = 1;
    while (i + count < chain.count && along[i + count]) ++count;
    Chain part = chain;
    part.start = (chain.start + i) % n;
    part.count = count;
    part.closed = false;
    parts.push_back(part);
  }
  return parts;
}

// Plans and keeps flaps on the marked positions of `side`, each part clear of those kept
// before it; returns the marked positions it found no room for.
std::vector<char> take(TabPlanner& planner, const Piece& piece, const Chain& side,
                       const std::vector<char>& along, std::vector<FlapPlan>& kept) {
  for (const Chain& part : marked_parts(side, piece, along)) {
    std::vector<FlapPlan> plans = planner.plan(part);
    planner.reserve(side, plans);
    for (FlapPlan& plan : plans) kept.push_back(std::move(plan));
  }
  std::vector<char> left = covered_positions(side, piece, kept);
  for (int i = 0; i < side.count; ++i) left[i] = along[i] && !left[i];
  return left;
}

// TabStyle::One: the first side takes what it has room for, the second what the first left.
bool one_side_first(TabPlanner& planner, const std::vector<Piece>& pieces, const Chain& first,
                    const Chain* second, const std::string& label) {
  std::vector<FlapPlan> first_plans = planner.plan(first);
  std::vector<char> left = covered_positions(first, pieces[first.piece], first_plans);
  for (char& position : left) position = !position;
  bool any = !first_plans.empty();
  if (any) {
    planner.reserve(first, first_plans);
    planner.commit(first, first_plans, label);
  }
  if (!second) return any;
  // The parts of the second side are planned apart and kept together.
  std::vector<FlapPlan> second_plans;
  for (const Chain& part : planner.partner_parts(first, left, *second))
    for (FlapPlan& plan : planner.plan(part)) second_plans.push_back(std::move(plan));
  if (second_plans.empty()) return any;
  planner.reserve(*second, second_plans);
  planner.commit(*second, second_plans, label);
  return true;
}

// TabStyle::Both: each side takes what it has room for.
bool each_side(TabPlanner& planner, const Chain& first, const Chain* second,
               const std::string& label) {
  bool any = false;
  for (const Chain* side : {&first, second}) {
    if (!side) continue;
    std::vector<FlapPlan> plans = planner.plan(*side);
    if (plans.empty()) continue;
    planner.reserve(*side, plans);
    planner.commit(*side, plans, label);
    any = true;
  }
  return any;
}

// A stretch of a seam whose tab one side takes: whole edges of the first side's chain
// (positions `from` .. `to` - 1), or the part (t0, t1) of the edge at position `from` alone.
struct Stretch {
  int from = 0, to = 0;
  double t0 = 0.0, t1 = 1.0;
  bool part() const { return t0 > 0.0 || t1 < 1.0; }
};

// The first side's chain in stretches of about run_mm: an edge of 1.5 runs or more in parts,
// shorter edges gathered until they are a run long (a last short rest joins the stretch before).
std::vector<Stretch> stretches(const Chain& chain, const Piece& piece, const StripData& data,
                               double run_mm) {
  const auto& loop = piece.loops[chain.loop];
  const int n = static_cast<int>(loop.size());
  std::vector<Stretch> out;
  bool open = false;  // the last stretch gathers edges until it is a run long
  double gathered = 0;
  for (int i = 0; i < chain.count; ++i) {
    const PieceEdge& e = loop[(chain.start + i) % n];
    const double length = (data.points[e.v1] - data.points[e.v0]).norm();
    if (length >= 1.5 * run_mm) {
      const int parts = static_cast<int>(std::lround(length / run_mm));
      for (int k = 0; k < parts; ++k)
        out.push_back({i, i + 1, double(k) / parts, k + 1 == parts ? 1.0 : double(k + 1) / parts});
      open = false;
      continue;
    }
    if (open) {
      out.back().to = i + 1;
    } else {
      out.push_back({i, i + 1});
      open = true;
      gathered = 0;
    }
    gathered += length;
    if (gathered >= run_mm) open = false;
  }
  const std::size_t k = out.size();
  if (open && gathered < 0.5 * run_mm && k >= 2 && !out[k - 2].part() &&
      out[k - 2].to == out[k - 1].from) {
    out[k - 2].to = out[k - 1].to;
    out.pop_back();
  }
  return out;
}

// TabStyle::Alternate: the first side's chain in stretches of about run_mm, taken in turn by
// the first side and the second; what a stretch's side has no room for goes to the other side.
bool alternate_sides(TabPlanner& planner, const std::vector<Piece>& pieces,
                     const std::vector<StripData>& strips, const Chain& first, const Chain* second,
                     const std::string& label, double run_mm) {
  const Piece& first_piece = pieces[first.piece];
  const std::vector<Stretch> parts =
      second ? stretches(first, first_piece, strips[first_piece.strip], run_mm)
             : std::vector<Stretch>{};
  if (parts.size() < 2) return one_side_first(planner, pieces, first, second, label);
  const Piece& second_piece = pieces[second->piece];
  std::vector<FlapPlan> first_kept, second_kept;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Stretch& stretch = parts[k];
    std::vector<char> on_first(first.count, 0);
    for (int i = stretch.from; i < stretch.to; ++i) on_first[i] = 1;
    const std::vector<Chain> on_second = planner.partner_parts(first, on_first, *second);
    const bool first_turn = k % 2 == 0;
    if (stretch.part()) {
      // Part of one edge: its partner runs the other way.
      Chain edge = first;
      edge.start =
          (first.start + stretch.from) % static_cast<int>(first_piece.loops[first.loop].size());
      auto on = [&](bool first_side) {
        if (first_side) return planner.plan_part(edge, stretch.t0, stretch.t1);
        if (on_second.empty()) return std::vector<FlapPlan>{};
        return planner.plan_part(on_second.front(), 1.0 - stretch.t1, 1.0 - stretch.t0);
      };
      for (const bool first_side : {first_turn, !first_turn}) {
        std::vector<FlapPlan> plans = on(first_side);
        if (plans.empty()) continue;
        planner.reserve(first_side ? first : *second, plans);
        for (FlapPlan& plan : plans)
          (first_side ? first_kept : second_kept).push_back(std::move(plan));
        break;
      }
      continue;
    }
    if (first_turn) {
      const std::vector<char> left = take(planner, first_piece, first, on_first, first_kept);
      take(planner, second_piece, *second,
           positions_of(*second, second_piece, planner.partner_parts(first, left, *second)),
           second_kept);
    } else {
      const std::vector<char> left =
          take(planner, second_piece, *second, positions_of(*second, second_piece, on_second),
               second_kept);
      take(planner, first_piece, first,
           positions_of(first, first_piece, planner.partner_parts(*second, left, first)),
           first_kept);
    }
  }
  if (!first_kept.empty()) planner.commit(first, first_kept, label);
  if (!second_kept.empty()) planner.commit(*second, second_kept, label);
  return !first_kept.empty() || !second_kept.empty();
}

}  // namespace

void add_tabs(std::vector<Piece>& pieces, const std::vector<StripData>& strips,
              const std::vector<Chain>& chains, const std::vector<SeamPair>& pairs,
              const SeamEdges& seams, const LayoutOptions& options,
              std::vector<std::string>& warnings) {
  TabPlanner planner(pieces, strips, seams, options);
  for (const SeamPair& pair : pairs) {
    int first = pair.first, second = pair.second;
    if (second >= 0 &&
        chain_key(chains[second], pieces, strips) < chain_key(chains[first], pieces, strips))
      std::swap(first, second);
    const Chain* other = second >= 0 ? &chains[second] : nullptr;
    bool any = false;
    switch (options.tab_style) {
      case TabStyle::One:
      case TabStyle::None:
        any = one_side_first(planner, pieces, chains[first], other, pair.printed);
        break;
      case TabStyle::Both:
        any = each_side(planner, chains[first], other, pair.printed);
        break;
      case TabStyle::Alternate:
        any = alternate_sides(planner, pieces, strips, chains[first], other, pair.printed,
                              options.alternate_run_mm);
        break;
    }
    if (!any)
      warnings.push_back("seam " + pair.printed + " has no room for a glue tab on either side");
  }
}

}  // namespace papercraft::layout_internal
