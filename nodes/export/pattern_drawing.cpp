#include "nodes/export/pattern_drawing.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/errors.h"

namespace papercraft {
namespace {

constexpr double kGentleMarkMm = 3.0;

struct Pens {
  Pen cut, mountain, valley, print;
  std::string tab_fill;
  std::string text;
  Pen gentle_mountain, gentle_valley;
  std::string engrave = "#000000";
};

Pens preset_pens(StylePreset preset) {
  switch (preset) {
    case StylePreset::Laser:
      // Hairlines: laser software treats sub-0.1 mm red/blue strokes as vector cut/score.
      return {{"#ff0000", 0.025, {}},
              {"#0000ff", 0.025, {}},
              {"#0000ff", 0.025, {2.0, 1.0}},
              {"#000000", 0.1, {}},
              "",
              "#000000",
              {"#8080ff", 0.025, {}},
              {"#8080ff", 0.025, {0.5, 1.0}},
              "#00a000"};
    case StylePreset::Cutter:
      return {{"#000000", 0.1, {}},
              {"#00a000", 0.1, {3.0, 1.0, 0.6, 1.0}},
              {"#0080ff", 0.1, {1.5, 1.0}},
              {"#000000", 0.2, {}},
              "",
              "#000000",
              {"#80d080", 0.1, {}},
              {"#80c0ff", 0.1, {0.5, 1.0}}};
    case StylePreset::Print:
      break;
  }
  return {{"#000000", 0.25, {}},
          {"#c00000", 0.2, {3.0, 1.0, 0.6, 1.0}},
          {"#0050c0", 0.2, {1.5, 1.0}},
          {"#000000", 0.25, {}},
          "#e6e6e6",
          "#000000",
          {"#e8a0a0", 0.12, {}},
          {"#a0b8e8", 0.12, {0.6, 0.6}}};
}

// A gentle fold as two short marks where the ruling meets the piece's edges: enough to
// show where to curve the paper without a line across every ruling.
void add_gentle_marks(std::vector<std::vector<Vec2>>& polylines, const FoldLine& fold) {
  const Vec2 d = fold.b - fold.a;
  const double length = d.norm();
  if (length <= 3 * kGentleMarkMm) {
    polylines.push_back({fold.a, fold.b});
    return;
  }
  const Vec2 step = d * (kGentleMarkMm / length);
  polylines.push_back({fold.a, fold.a + step});
  polylines.push_back({fold.b - step, fold.b});
}

}  // namespace

StylePreset style_preset_from_name(std::string_view name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "print") return StylePreset::Print;
  if (lower == "laser") return StylePreset::Laser;
  if (lower == "cutter") return StylePreset::Cutter;
  throw InvalidInputException("unknown style preset '" + std::string(name) +
                              "': use print, laser or cutter");
}

namespace {

// Points nearer than this (mm) are one: the SVG prints 3 decimals, so a shorter segment would
// print as one of zero length (a fold line's dash ending at a fan's apex, say).
constexpr double kSamePointMm = 2e-3;

// A polyline without repeated points (no zero-length segment reaches a cutter); empty when
// fewer than two distinct points remain.
std::vector<Vec2> without_repeats(const std::vector<Vec2>& line, bool closed) {
  std::vector<Vec2> out;
  for (const Vec2& p : line)
    if (out.empty() || (p - out.back()).norm() > kSamePointMm) out.push_back(p);
  if (closed)
    while (out.size() > 1 && (out.front() - out.back()).norm() <= kSamePointMm) out.pop_back();
  if (out.size() < 2) out.clear();
  return out;
}

void drop_repeats(DrawLayer& layer) {
  for (DrawPath& path : layer.paths) {
    std::vector<std::vector<Vec2>> lines;
    for (const auto& line : path.polylines) {
      auto clean = without_repeats(line, path.closed);
      if (!clean.empty()) lines.push_back(std::move(clean));
    }
    path.polylines = std::move(lines);
  }
  layer.paths.erase(std::remove_if(layer.paths.begin(), layer.paths.end(),
                                   [](const DrawPath& p) { return p.polylines.empty(); }),
                    layer.paths.end());
}

}  // namespace

std::vector<DrawLayer> registration_marks(const PageSize& page) {
  // Silhouette's convention: a filled 5 mm square at the top left, 20 mm L-brackets 0.3 mm
  // thick at the top right and the bottom left, all 10 mm from the paper's edges.
  constexpr double kInset = 10.0, kSquare = 5.0, kArm = 20.0, kThick = 0.3;
  const double w = page.width_mm, h = page.height_mm;
  DrawLayer marks{"regmarks", {}, {}};
  DrawPath square{{}, true, false, Pen{"#000000", 0.0, {}}, "#000000"};
  square.polylines.push_back({{kInset, kInset},
                              {kInset + kSquare, kInset},
                              {kInset + kSquare, kInset + kSquare},
                              {kInset, kInset + kSquare}});
  // Each bracket as one filled L: its corner on the inset lines, arms along the edges.
  const Vec2 tr(w - kInset, kInset), bl(kInset, h - kInset);
  square.polylines.push_back({tr, tr + Vec2(0, kArm), tr + Vec2(-kThick, kArm),
                              tr + Vec2(-kThick, kThick), tr + Vec2(-kArm, kThick),
                              tr + Vec2(-kArm, 0)});
  square.polylines.push_back({bl, bl + Vec2(kArm, 0), bl + Vec2(kArm, -kThick),
                              bl + Vec2(kThick, -kThick), bl + Vec2(kThick, -kArm),
                              bl + Vec2(0, -kArm)});
  marks.paths.push_back(std::move(square));
  return {marks};
}

std::vector<DrawLayer> pattern_page_drawing(const PatternLayout& layout, int page_index,
                                            const StyleOptions& style) {
  if (page_index < 0 || page_index >= static_cast<int>(layout.pages.size()))
    throw InvalidInputException("page " + std::to_string(page_index) + " does not exist (the " +
                                "layout has " + std::to_string(layout.pages.size()) + " pages)");
  const Page& page = layout.pages[page_index];
  const Pens pens = preset_pens(style.preset);
  DrawLayer print{"print", {}, {}}, tabs{"tabs", {}, {}}, labels{"labels", {}, {}};
  DrawLayer valley{"valley", {}, {}}, mountain{"mountain", {}, {}}, cut{"cut", {}, {}};

  const ScaleBar& bar = page.scale_bar;
  if (bar.length_mm > 0) {
    DrawPath ruler{{}, false, true, pens.print, ""};
    ruler.polylines.push_back({bar.start, bar.start + Vec2(bar.length_mm, 0)});
    const int ticks = static_cast<int>(std::lround(bar.length_mm / bar.tick_spacing_mm));
    for (int i = 0; i <= ticks; ++i) {
      const Vec2 at = bar.start + Vec2(i * bar.tick_spacing_mm, 0);
      const double height = (i == 0 || i == ticks) ? bar.tick_height_mm : 0.5 * bar.tick_height_mm;
      ruler.polylines.push_back({at, at - Vec2(0, height)});
    }
    print.paths.push_back(std::move(ruler));
    print.texts.push_back({bar.caption, pens.text});
  }
  if (!page.footer.text.empty()) {
    Label footer = page.footer;
    if (!style.title.empty()) {
      // Keep the right end where the layout put it.
      const double old_width = 0.6 * footer.size_mm * static_cast<double>(footer.text.size());
      footer.text = style.title + " - " + footer.text;
      const double new_width = 0.6 * footer.size_mm * static_cast<double>(footer.text.size());
      footer.position.x() -= 0.5 * (new_width - old_width);
    }
    print.texts.push_back({footer, pens.text});
  }

  std::vector<const PlacedPiece*> placed;
  for (const PlacedPiece& piece : page.pieces) placed.push_back(&piece);
  for (const PlacedPiece& joint : page.joints) placed.push_back(&joint);
  for (const PlacedPiece* each : placed) {
    const PlacedPiece& piece = *each;
    DrawPath outline{piece.cut_outline, true, true, pens.cut, ""};
    cut.paths.push_back(std::move(outline));
    DrawPath hills{{}, false, true, pens.mountain, ""}, dales{{}, false, true, pens.valley, ""};
    DrawPath gentle_hills{{}, false, true, pens.gentle_mountain, ""};
    DrawPath gentle_dales{{}, false, true, pens.gentle_valley, ""};
    for (const FoldLine& fold : piece.folds) {
      const bool mountain = fold.kind == FoldKind::Mountain;
      if (fold.gentle)
        add_gentle_marks((mountain ? gentle_hills : gentle_dales).polylines, fold);
      else
        (mountain ? hills : dales).polylines.push_back({fold.a, fold.b});
    }
    if (!gentle_hills.polylines.empty()) mountain.paths.push_back(std::move(gentle_hills));
    if (!gentle_dales.polylines.empty()) valley.paths.push_back(std::move(gentle_dales));
    const bool textured_tabs = style.images != nullptr;
    // A textured tab shows the texture, not the grey fill; its outline is the cut line.
    DrawPath flaps{{}, true, false, pens.print, textured_tabs ? "" : pens.tab_fill};
    // A tab folds away from the outside: a mountain seen from the front, a valley from the back.
    DrawPath& tab_folds = layout.print_side == PrintSide::Back ? dales : hills;
    for (const Tab& tab : piece.tabs) {
      for (const auto& base : tab.bases) tab_folds.polylines.push_back(base);
      for (const auto& flap : tab.flaps) flaps.polylines.push_back(flap);
    }
    if (!hills.polylines.empty()) mountain.paths.push_back(std::move(hills));
    if (!dales.polylines.empty()) valley.paths.push_back(std::move(dales));
    if (!flaps.polylines.empty()) tabs.paths.push_back(std::move(flaps));
    if (!piece.marks.empty()) {
      DrawPath marks{{}, false, true, pens.print, ""};
      for (const auto& mark : piece.marks) marks.polylines.push_back({mark[0], mark[1]});
      labels.paths.push_back(std::move(marks));
    }
    DrawPath leaders{{}, false, true, pens.print, ""};
    leaders.pen.width_mm = std::min(leaders.pen.width_mm, 0.15);
    for (const Label& label : piece.labels)
      if (label.leader.size() >= 2 && (label.leader.back() - label.leader.front()).norm() > 1e-6)
        leaders.polylines.push_back(label.leader);
    if (!leaders.polylines.empty()) labels.paths.push_back(std::move(leaders));
    for (const Label& label : piece.labels) labels.texts.push_back({label, pens.text});
    labels.texts.push_back({piece.number, pens.text});
  }
  std::vector<DrawLayer> layers;
  switch (style.preset) {
    case StylePreset::Print:
      layers = {print, tabs, labels, valley, mountain, cut};
      break;
    case StylePreset::Laser: {
      // Everything that is not cut or scored is engraved, in its own colour on its own layer.
      DrawLayer engrave{"engrave", {}, {}};
      for (DrawLayer* layer : {&print, &labels}) {
        for (DrawPath& path : layer->paths) {
          path.pen.colour = pens.engrave;
          engrave.paths.push_back(path);
        }
        for (DrawText& text : layer->texts) {
          text.colour = pens.engrave;
          engrave.texts.push_back(text);
        }
      }
      DrawLayer score{"score", {}, {}};
      for (DrawLayer* layer : {&valley, &mountain})
        score.paths.insert(score.paths.end(), layer->paths.begin(), layer->paths.end());
      layers = {engrave, score, cut};
      break;
    }
    case StylePreset::Cutter: {
      // Printed first, then cut along the outline of piece and tabs; folds on a score layer
      // the cutter can perforate or skip; marks to register the print.
      DrawLayer score{"score", {}, {}};
      for (DrawLayer* layer : {&valley, &mountain})
        score.paths.insert(score.paths.end(), layer->paths.begin(), layer->paths.end());
      layers = registration_marks(layout.page);
      layers.push_back(print);
      layers.push_back(labels);
      layers.push_back(score);
      layers.push_back(cut);
      break;
    }
  }
  for (DrawLayer& layer : layers) drop_repeats(layer);
  return layers;
}

}  // namespace papercraft
