// layout_pages, the layout stage's top level: the strips laid out several ways (layout_pass),
// long thin strips split or not, triangles divided or not, and the cheapest kept by
// compare_layouts (layout_cost.h).
#include "nodes/layout/pages.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>

#include "nodes/layout/divide_triangles.h"
#include "nodes/layout/layout_cost.h"
#include "nodes/layout/layout_pass.h"
#include "nodes/layout/prepare_layout.h"
#include "nodes/layout/print_side.h"

namespace papercraft {

using layout_internal::compare_layouts;
using layout_internal::divide_triangles;
using layout_internal::LabelCache;
using layout_internal::layout_pass;
using layout_internal::LayoutPass;
using layout_internal::prepare_layout;
using layout_internal::PreparedLayout;
using layout_internal::SplitLong;
using layout_internal::strip_fits;
using layout_internal::StripData;
using layout_internal::Verdict;

std::vector<int> strips_exceeding_page(const std::vector<FlatStrip>& strips,
                                       const LayoutOptions& options) {
  const PreparedLayout p = prepare_layout(strips, options);
  std::vector<int> ids;
  for (const StripData& data : p.strips)
    if (!data.triangles.empty() && !strip_fits(data, p)) ids.push_back(data.strip->id);
  return ids;
}

namespace {

// The passes of layout_pages on strips as they are: whole, then with the long thin strips that
// fit split in half pages, then also those larger than the page (split only to fit it their
// parts would stay long and bent), then with them split where they bend; each judged against
// the best so far by compare_layouts. A pass that splits no strip is no candidate.
LayoutPass layout_tries(const std::vector<FlatStrip>& strips, const LayoutOptions& options,
                        bool divided) {
  // The pieces the passes share (most of them) get their labels arranged once.
  LabelCache labels;
  LayoutPass best = layout_pass(strips, options, SplitLong::None, nullptr, &labels, divided);
  const layout_internal::LongStrips whole = best.long_strips;
  // No long thin strip is found unless nesting with split_long_strips.
  if (best.cost.pages < 2 || whole.found + whole.oversize == 0) return best;
  const int unsplit_pages = best.cost.pages;
  const int unsplit_pieces = best.cost.pieces;
  bool kept = false, bends = false;
  auto judge = [&](SplitLong mode, const std::vector<char>* chosen) {
    LayoutPass candidate = layout_pass(strips, options, mode, chosen, &labels, divided);
    if (candidate.long_strips.split == 0) return Verdict::Worse;
    const Verdict verdict = compare_layouts(candidate.cost, best.cost, options.splits_per_page);
    if (verdict == Verdict::Better) {
      best = std::move(candidate);
      kept = true;
      bends = mode == SplitLong::Bends;
    }
    return verdict;
  };
  if (whole.found > 0) judge(SplitLong::Fitting, nullptr);
  if (whole.oversize > 0) judge(SplitLong::All, nullptr);
  // Split where they bend: every long thin strip, then (where that saves pages, but too few
  // for the pieces it adds) only the half, the quarter, the eighth of them that waste the most
  // paper round them, till one is not too costly.
  if (judge(SplitLong::Bends, nullptr) == Verdict::TooCostly) {
    std::vector<std::pair<double, int>> order = whole.waste;
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    std::size_t previous = order.size();
    for (std::size_t divisor : {2, 4, 8}) {
      const std::size_t count = std::max<std::size_t>(1, order.size() / divisor);
      if (count >= previous) continue;
      previous = count;
      std::vector<char> chosen(strips.size(), 0);
      for (std::size_t i = 0; i < count; ++i) chosen[order[i].second] = 1;
      if (judge(SplitLong::Bends, &chosen) != Verdict::TooCostly) break;
    }
  }
  if (kept) {
    const int added = best.cost.pieces - unsplit_pieces;
    const int count = std::abs(added);
    best.layout.warnings.push_back(
        "long thin strips" +
        std::string(bends ? " split where they bend" : " split in parts of half a page") +
        " make " + std::to_string(count) + (added < 0 ? " fewer " : " more ") +
        (count == 1 ? "piece" : "pieces") + ", which saves " +
        std::to_string(unsplit_pages - best.cost.pages) + " of " + std::to_string(unsplit_pages) +
        " pages");
  }
  return best;
}

// Triangles divided at most into this many, all strips together.
constexpr std::size_t kMostDividedTriangles = 3000;

// How many parts each edge of every triangle is divided into before the layout: where some
// strip fits no page and has triangles with an edge longer than a third of the page's shorter
// side (a coarse mesh printed large), enough parts that none is, within
// kMostDividedTriangles; else 1.
int divisions(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  if (strips.empty() || options.packing != PackingMethod::Nest) return 1;
  const PreparedLayout p = prepare_layout(strips, options);
  bool all_fit = true;
  double longest = 0;
  std::size_t triangles = 0;
  for (const StripData& data : p.strips) {
    if (!data.triangles.empty() && !strip_fits(data, p)) all_fit = false;
    triangles += data.triangles.size();
    for (int t : data.triangles) {
      const Triangle& tri = data.strip->triangles[t];
      for (int i = 0; i < 3; ++i)
        longest = std::max(longest, (data.points[tri[(i + 1) % 3]] - data.points[tri[i]]).norm());
    }
  }
  if (all_fit || triangles == 0) return 1;
  const double part = (std::min(p.area.x(), p.area.y()) - 2 * p.reserve) / 3.0;
  if (part <= 0) return 1;
  const int wanted = static_cast<int>(std::ceil(longest / part));
  const int most =
      static_cast<int>(std::floor(std::sqrt(double(kMostDividedTriangles) / double(triangles))));
  const int n = std::min(wanted, most);
  return n >= 2 ? n : 1;
}

// layout_pages before it mirrors the pages for printing on the back.
PatternLayout front_layout(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  LayoutPass layout = layout_tries(strips, options, false);
  const int n = divisions(strips, options);
  if (n <= 1) return std::move(layout.layout);
  // A strip no page holds, of triangles too large to cut it well at their edges: laid out
  // again with every triangle divided (the same surface), kept where compare_layouts prefers
  // it.
  LayoutPass divided = layout_tries(divide_triangles(strips, n), options, true);
  if (compare_layouts(divided.cost, layout.cost, options.splits_per_page) != Verdict::Better)
    return std::move(layout.layout);
  std::unordered_map<int, std::size_t> vertices;  // strip id -> its vertex count
  for (const FlatStrip& strip : strips) vertices[strip.id] = strip.vertices3d.size();
  for (Page& page : divided.layout.pages)
    for (PlacedPiece& piece : page.pieces) {
      const auto it = vertices.find(piece.strip_id);
      for (int& v : piece.strip_vertex)
        if (it == vertices.end() || v >= static_cast<int>(it->second)) v = -1;
    }
  const int over = layout.cost.overflowing, over_divided = divided.cost.overflowing;
  divided.layout.warnings.push_back(
      "triangles divided in " + std::to_string(n * n) +
      " to cut strips larger than a page across them: " + std::to_string(divided.cost.pages) +
      " pages instead of " + std::to_string(layout.cost.pages) +
      (over > over_divided
           ? ", and " + std::to_string(over - over_divided) + " fewer pieces overflow their page"
           : ""));
  return std::move(divided.layout);
}

}  // namespace

PatternLayout layout_pages(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  PatternLayout layout = front_layout(strips, options);
  if (options.print_side == PrintSide::Back) mirror_for_back_printing(layout);
  return layout;
}

}  // namespace papercraft
