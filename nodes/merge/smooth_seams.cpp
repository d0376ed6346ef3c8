// smooth_seams: triangles handed across seams where that makes the pieces cheaper to cut and
// glue, one move at a time from a queue of gains: a triangle at a sawtooth corner of a piece's
// outline goes to the neighbour across its seam when the union welds along every edge they
// share and what the pieces cost a person drops (MoveCost).
#include <algorithm>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <utility>
#include <vector>

#include "core/effort.h"
#include "core/flat_boundary.h"
#include "core/piece_width.h"
#include "core/seams.h"
#include "nodes/merge/chains.h"
#include "nodes/merge/congruent.h"
#include "nodes/merge/move_cost.h"
#include "nodes/merge/rigid_join.h"
#include "nodes/merge/strip_parts.h"
#include "nodes/merge/transfer.h"
#include "nodes/merge/validate.h"

namespace papercraft {
namespace {

using merge_detail::corners_key;
using merge_detail::exact_key;
using merge_detail::MoveCost;
using merge_detail::PairCandidate;
using merge_detail::rim_of;
using merge_detail::shared_boundaries;
using merge_detail::strips_beside;
using merge_detail::take_triangle;
using merge_detail::try_merge;

// A triangle of one piece handed to a neighbour, and what it gains. Strips are named by id (an
// index moves when a piece goes), with the versions they had when the move was judged.
struct Move {
  double gain = 0.0;
  int from = -1, to = -1;             // strip ids
  std::array<double, 9> triangle{};  // corners_key in `from`
  int from_version = 0, to_version = 0;
  bool operator<(const Move& other) const { return gain < other.gain; }
};

struct Limits {
  double min_area = 0.0, min_width = 0.0, narrow_share = 1.0;
};

double share_of(const FlatStrip& strip, double min_width) {
  return min_width > 0.0 ? narrow_area_fraction(strip.vertices2d, strip.triangles, min_width) : 0.0;
}

// Triangle `t` of strips[from] moved into strips[to]: the rest of `from` and the union, or false
// where the move is not legal: the rest falls under min_area or meets the part at a point, the
// part lands on the neighbour or does not weld along every edge it shares (a slit), or either
// piece gets narrower than min_width over more than the bound (or than it was).
bool moved(const std::vector<FlatStrip>& strips, int from, int to, std::size_t t,
           const Limits& limits, const MergeOptions& options, FlatStrip& rest, FlatStrip& joined) {
  FlatStrip part;
  if (!take_triangle(strips[from], t, rest, part)) return false;
  if (flat_area(rest) < std::min(limits.min_area, flat_area(strips[from]))) return false;
  const std::vector<PairCandidate> pairs = shared_boundaries({strips[to], part});
  if (pairs.empty()) return false;
  std::set<int> on_rim;  // the part's points on the neighbour's rim: every one must weld
  for (const auto& chain : pairs[0].chains) on_rim.insert(chain.y.begin(), chain.y.end());
  if (!try_merge(strips[to], part, pairs[0].chains, options, joined) ||
      joined.vertices2d.size() !=
          strips[to].vertices2d.size() + part.vertices2d.size() - on_rim.size())
    return false;
  rest.boundary = flat_boundary(rest.triangles);
  return true;
}

bool keeps_wide(const FlatStrip& before, const FlatStrip& after, const Limits& limits) {
  if (!(limits.min_width > 0.0)) return true;
  return share_of(after, limits.min_width) <=
         std::max(share_of(before, limits.min_width), limits.narrow_share);
}

// The moves that pay out of strips[s]: each triangle at a sawtooth corner of its outline (page
// mm) with an edge on a neighbour's rim, handed to that neighbour.
void judge_strip(const std::vector<FlatStrip>& strips, int s, const Limits& limits,
                 const MergeOptions& options, const std::map<int, int>& version,
                 std::priority_queue<Move>& queue) {
  const FlatStrip& strip = strips[s];
  const double scale = options.mm_per_unit;
  std::set<int> corners;  // strip vertices at sawtooth corners
  for (std::size_t e = 0; e < strip.boundary.size();) {
    std::vector<Vec2> loop;
    std::vector<int> vertex;
    std::size_t k = e;
    do {
      loop.push_back(scale * strip.vertices2d[strip.boundary[k].v0]);
      vertex.push_back(strip.boundary[k].v0);
      ++k;
    } while (k < strip.boundary.size() && strip.boundary[k].v0 == strip.boundary[k - 1].v1);
    for (int i : sawtooth_corners(loop)) corners.insert(vertex[i]);
    e = k;
  }
  if (corners.empty()) return;
  for (int to : strips_beside(strips, s)) {
    const std::set<std::array<double, 6>> rim = rim_of(strips[to]);
    std::unique_ptr<MoveCost> cost;
    for (std::size_t t = 0; t < strip.triangles.size(); ++t) {
      const Triangle& tri = strip.triangles[t];
      bool at_corner = false, on_rim = false;
      for (int k = 0; k < 3; ++k) {
        at_corner = at_corner || corners.count(tri[k]);
        on_rim = on_rim || rim.count(exact_key(strip.vertices3d[tri[k]],
                                               strip.vertices3d[tri[(k + 1) % 3]]));
      }
      if (!at_corner || !on_rim) continue;
      FlatStrip rest, joined;
      if (!moved(strips, s, to, t, limits, options, rest, joined)) continue;
      if (!cost) cost = std::make_unique<MoveCost>(strips, std::vector<int>{s, to}, options,
                                                   limits.min_area);
      const double gain = cost->gain({&rest, &joined});
      if (!(gain > 0.0)) continue;
      queue.push({gain, strip.id, strips[to].id, corners_key(strip, tri), version.at(strip.id),
                  version.at(strips[to].id)});
    }
  }
}

}  // namespace

std::vector<FlatStrip> smooth_seams(std::vector<FlatStrip> strips, double min_area,
                                    double min_width, double narrow_share,
                                    const MergeOptions& options) {
  merge_detail::validate(strips, options);
  if (!(options.mm_per_unit > 0.0)) return strips;
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);
  const Limits limits{min_area, min_width, narrow_share};
  std::map<int, int> version;  // per strip id: bumped when the strip changes
  for (const FlatStrip& strip : strips) version[strip.id] = 0;
  const auto index_of = [&](int id) {
    for (int s = 0; s < static_cast<int>(strips.size()); ++s)
      if (strips[s].id == id) return s;
    return -1;
  };
  std::priority_queue<Move> queue;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    judge_strip(strips, s, limits, options, version, queue);
  // Each move takes away at least one sawtooth corner's worth of effort, so the moves are
  // bounded; the budget only guards against a cycle of equal gains.
  const int most_moves = 4 * static_cast<int>(strips.size()) + 16;
  for (int moves = 0; !queue.empty() && moves < most_moves;) {
    const Move move = queue.top();
    queue.pop();
    if (version[move.from] != move.from_version || version[move.to] != move.to_version) continue;
    const int from = index_of(move.from), to = index_of(move.to);
    std::size_t t = 0;
    while (t < strips[from].triangles.size() &&
           corners_key(strips[from], strips[from].triangles[t]) != move.triangle)
      ++t;
    FlatStrip rest, joined;
    if (t == strips[from].triangles.size() ||
        !moved(strips, from, to, t, limits, options, rest, joined) ||
        !keeps_wide(strips[from], rest, limits) || !keeps_wide(strips[to], joined, limits))
      continue;
    // A move judged before a neighbour changed is judged again: their seams count in its gain.
    if (!(MoveCost(strips, {from, to}, options, min_area).gain({&rest, &joined}) > 0.0)) continue;
    strips[from] = std::move(rest);
    strips[to] = std::move(joined);
    ++version[move.from], ++version[move.to], ++moves;
    std::set<int> again{from, to};  // and the neighbours, whose corners at the seam may turn
    for (int s : {from, to})
      for (int n : strips_beside(strips, s)) again.insert(n);
    for (int s : again) judge_strip(strips, s, limits, options, version, queue);
  }
  label_seams(strips);
  return strips;
}

}  // namespace papercraft
