// layout_pages, the layout stage's top level: strips prepared and split to fit, seams paired,
// tabs and labels added, pieces oriented, packed and placed on pages with their furniture.
#include "nodes/layout/pages.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "core/errors.h"
#include "nodes/layout/annotations.h"
#include "nodes/layout/divide_triangles.h"
#include "nodes/layout/format_mm.h"
#include "nodes/layout/nesting.h"
#include "nodes/layout/pieces.h"
#include "nodes/layout/polygon_2d.h"
#include "nodes/layout/print_side.h"
#include "nodes/layout/rectangle_packing.h"
#include "nodes/layout/seam_pairing.h"
#include "nodes/layout/split_to_fit.h"
#include "nodes/layout/tab_styles.h"

namespace papercraft {

using layout_internal::add_alignment_marks;
using layout_internal::add_tabs;
using layout_internal::arrange_labels;
using layout_internal::Chain;
using layout_internal::chain_label;
using layout_internal::chain_length;
using layout_internal::clear_of_text;
using layout_internal::convex_hull;
using layout_internal::convex_overlap;
using layout_internal::cross;
using layout_internal::divide_triangles;
using layout_internal::Flap;
using layout_internal::format_mm;
using layout_internal::hull_fits;
using layout_internal::kDegree;
using layout_internal::LabelCache;
using layout_internal::leader_boxes;
using layout_internal::match_seam_edges;
using layout_internal::nest_shapes;
using layout_internal::NestOptions;
using layout_internal::NestPlacement;
using layout_internal::NestShape;
using layout_internal::OrientedBox;
using layout_internal::pack_with_spacing;
using layout_internal::PackResult;
using layout_internal::pair_chains;
using layout_internal::Piece;
using layout_internal::piece_folds;
using layout_internal::piece_loops;
using layout_internal::piece_name;
using layout_internal::piece_number;
using layout_internal::piece_points;
using layout_internal::PieceEdge;
using layout_internal::PieceLabel;
using layout_internal::PieceTab;
using layout_internal::prepare_strip;
using layout_internal::seam_chains;
using layout_internal::SeamEdges;
using layout_internal::SeamPair;
using layout_internal::signed_area;
using layout_internal::split_to_fit;
using layout_internal::strip_name;
using layout_internal::StripData;
using layout_internal::text_box;
using layout_internal::text_boxes;
using layout_internal::tightest_box;
using layout_internal::validate_strip;

namespace {

std::string format_number(double value, int precision) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

double upright_degrees(const Vec2& page_direction) {
  double angle = std::atan2(page_direction.y(), page_direction.x()) / kDegree;
  if (angle > 90.0 + 1e-9) angle -= 180.0;
  if (angle <= -90.0 + 1e-9) angle += 180.0;
  return angle;
}

void validate_options(const LayoutOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v))
      throw InvalidInputException(std::string("layout option ") + name + " must be > 0");
  };
  auto non_negative = [](double v, const char* name) {
    if (!(v >= 0) || !std::isfinite(v))
      throw InvalidInputException(std::string("layout option ") + name + " must be >= 0");
  };
  positive(o.page.width_mm, "page width");
  positive(o.page.height_mm, "page height");
  non_negative(o.margin_mm, "margin_mm");
  non_negative(o.height_mm, "height_mm");
  non_negative(o.scale, "scale");
  non_negative(o.tab_width_mm, "tab_width_mm");
  non_negative(o.fold_angle_degrees, "fold_angle_degrees");
  non_negative(o.strong_fold_angle_degrees, "strong_fold_angle_degrees");
  non_negative(o.spacing_mm, "spacing_mm");
  positive(o.label_size_mm, "label_size_mm");
  positive(o.number_size_mm, "number_size_mm");
  non_negative(o.footer_mm, "footer_mm");
  if (!(o.tab_angle_degrees > 0 && o.tab_angle_degrees <= 90))
    throw InvalidInputException("layout option tab_angle_degrees must be in (0, 90]");
  positive(o.alternate_run_mm, "alternate_run_mm");
  if (!(o.scale > 0) && !(o.height_mm > 0))
    throw InvalidInputException("layout needs height_mm > 0 or scale > 0");
  if (o.splits_per_page < 1)
    throw InvalidInputException("layout option splits_per_page must be >= 1");
}

// Room kept around a piece for its tabs while splitting: a flap stays within its height of
// the seam but for the mitres at joints of up to 15 degrees and its short angled ends.
double tab_reserve_for(const LayoutOptions& o) {
  return o.tab_style == TabStyle::None ? 0.0 : 1.15 * o.tab_width_mm;
}

// The printable area less the footer (and the gap above it).
Vec2 usable_area(const LayoutOptions& o) {
  const double footer = o.footer_mm > 0 ? o.footer_mm + o.spacing_mm : 0.0;
  const Vec2 area(o.page.width_mm - 2 * o.margin_mm, o.page.height_mm - 2 * o.margin_mm - footer);
  const double reserve = 2 * tab_reserve_for(o);
  if (area.x() - reserve < 1.0 || area.y() - reserve < 1.0)
    throw InvalidInputException("page " + format_mm(o.page.width_mm) + " x " +
                                format_mm(o.page.height_mm) +
                                " mm leaves no room inside margins "
                                "of " +
                                format_mm(o.margin_mm) + " mm for pieces with tabs");
  return area;
}

}  // namespace

double layout_scale(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  validate_options(options);
  if (options.scale > 0) return options.scale;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const FlatStrip& strip : strips)
    for (const Vec3& v : strip.vertices3d) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  const double side = (hi - lo).maxCoeff();
  if (!(side > 0) || !std::isfinite(side))
    throw InvalidInputException(
        "cannot scale the strips to height_mm: their 3D bounding box has no extent (give a "
        "scale in mm per model unit instead)");
  return options.height_mm / side;
}

namespace {

struct Prepared {
  double mm_per_unit = 1;
  Vec2 area = Vec2::Zero();
  double reserve = 0;
  double tolerance3d = 0;
  std::vector<StripData> strips;
};

Prepared prepare(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  validate_options(options);
  std::set<int> ids;
  for (const FlatStrip& strip : strips) {
    validate_strip(strip);
    if (!ids.insert(strip.id).second)
      throw InvalidInputException("two strips have id " + std::to_string(strip.id));
  }
  Prepared p;
  p.area = usable_area(options);
  p.reserve = tab_reserve_for(options);
  if (strips.empty()) {
    p.mm_per_unit = options.scale > 0 ? options.scale : 1.0;
    return p;
  }
  p.mm_per_unit = layout_scale(strips, options);
  double largest = 0;
  for (const FlatStrip& strip : strips)
    for (const Vec3& v : strip.vertices3d) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  p.tolerance3d = 1e-9 * std::max(largest, 1e-300);
  for (const FlatStrip& strip : strips) p.strips.push_back(prepare_strip(strip, p.mm_per_unit));
  return p;
}

bool strip_fits(const StripData& data, const Prepared& p, const std::vector<int>& triangles) {
  return hull_fits(convex_hull(piece_points(data, triangles)), p.area.x() - 2 * p.reserve,
                   p.area.y() - 2 * p.reserve);
}

bool strip_fits(const StripData& data, const Prepared& p) {
  return strip_fits(data, p, data.triangles);
}

struct Orientation {
  OrientedBox box;
  bool fits = true;
};

// The boxes of the texts printed beside the piece (PieceLabel::outside).
std::vector<std::array<Vec2, 4>> outside_text(const Piece& piece) {
  std::vector<std::array<Vec2, 4>> boxes;
  for (const PieceLabel& label : piece.labels) {
    if (label.outside)
      boxes.push_back(text_box(label.position, label.direction, label.size, label.text.size()));
    for (const auto& box : leader_boxes(label.leader)) boxes.push_back(box);
  }
  if (piece.number && piece.number->outside)
    boxes.push_back(text_box(piece.number->position, piece.number->direction, piece.number->size,
                             piece.number->text.size()));
  return boxes;
}

Orientation orient_piece(const StripData& data, const Piece& piece, const Vec2& area) {
  std::vector<Vec2> points = piece_points(data, piece.triangles);
  for (const Flap& flap : piece.flaps)
    points.insert(points.end(), flap.outer.begin(), flap.outer.end());
  for (const auto& box : outside_text(piece)) points.insert(points.end(), box.begin(), box.end());
  Orientation o;
  o.box = tightest_box(convex_hull(points), area.x(), area.y(), &o.fits);
  return o;
}

// The piece on the page: page = flip_y(rotate(theta) * p) + translation (p in the strip frame,
// mm).
PlacedPiece place_piece_at(const StripData& data, const Piece& piece, const OrientedBox& box,
                           double theta, const Vec2& translation, const LayoutOptions& options,
                           double mm_per_unit);

PlacedPiece place_piece(const StripData& data, const Piece& piece, const OrientedBox& box,
                        const PackedRectangle& at, const LayoutOptions& options,
                        double mm_per_unit) {
  double theta = -box.angle;
  double min_x = box.min.x(), max_y = box.min.y() + box.size.y();
  if (at.rotated) {
    theta += std::numbers::pi / 2;
    min_x = -(box.min.y() + box.size.y());
    max_y = box.min.x() + box.size.x();
  }
  const Vec2 translation(options.margin_mm + at.x - min_x, options.margin_mm + at.y + max_y);
  return place_piece_at(data, piece, box, theta, translation, options, mm_per_unit);
}

PlacedPiece place_piece_at(const StripData& data, const Piece& piece, const OrientedBox& box,
                           double theta, const Vec2& translation, const LayoutOptions& options,
                           double mm_per_unit) {
  const FlatStrip& strip = *data.strip;
  Eigen::Matrix2d rotation;
  rotation << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  const Eigen::Matrix2d linear = Eigen::Vector2d(1, -1).asDiagonal() * rotation;
  auto to_page = [&](const Vec2& p) { return Vec2(linear * p + translation); };
  auto direction_degrees = [&](const Vec2& d) { return upright_degrees(linear * d); };

  PlacedPiece placed;
  placed.name = piece.name;
  placed.seams = piece.seams;
  placed.strip_id = strip.id;
  placed.piece_index = piece.index;
  placed.piece_count = piece.count;
  placed.transform.linear = linear * mm_per_unit;
  placed.transform.translation = translation;
  placed.transform.rotation_degrees = theta / kDegree;

  std::unordered_map<int, int> local;
  auto local_index = [&](int v) {
    auto [it, inserted] = local.emplace(v, static_cast<int>(placed.vertices.size()));
    if (inserted) {
      placed.vertices.push_back(to_page(data.points[v]));
      placed.strip_vertex.push_back(v);
      placed.points3d.push_back(strip.vertices3d[v]);
      if (!strip.uvs.empty()) placed.uvs.push_back(strip.uvs[v]);
    }
    return it->second;
  };
  for (int t : piece.triangles) {
    const Triangle& tri = strip.triangles[t];
    placed.triangles.push_back({local_index(tri[0]), local_index(tri[1]), local_index(tri[2])});
  }
  for (const auto& loop : piece.loops) {
    std::vector<Vec2> outline, cut;
    for (const PieceEdge& e : loop) {
      const Vec2 a = to_page(data.points[e.v0]), b = to_page(data.points[e.v1]);
      outline.push_back(a);
      if (e.flap >= 0) {
        // Around a flap over several edges, from its first edge's start.
        if (e.flap_first) {
          cut.push_back(a);
          for (const Vec2& q : piece.flaps[e.flap].outer) cut.push_back(to_page(q));
        }
      } else {
        // Around the flaps on this edge alone; one on part of it starts and ends on the edge.
        cut.push_back(a);
        for (const int f : e.edge_flaps) {
          const Flap& flap = piece.flaps[f];
          if ((flap.base.front() - data.points[e.v0]).norm() > 1e-9)
            cut.push_back(to_page(flap.base.front()));
          for (const Vec2& q : flap.outer) cut.push_back(to_page(q));
          if ((flap.base.back() - data.points[e.v1]).norm() > 1e-9)
            cut.push_back(to_page(flap.base.back()));
        }
      }
      placed.edges.push_back(
          {a, b, e.kind, e.printed, e.flap >= 0 || !e.edge_flaps.empty()});
    }
    placed.outline.push_back(std::move(outline));
    placed.cut_outline.push_back(std::move(cut));
  }
  const auto boxes = text_boxes(piece);
  for (FoldLine fold : clear_of_text(
           piece_folds(data, piece, options.fold_angle_degrees, options.strong_fold_angle_degrees),
           boxes)) {
    fold.a = to_page(fold.a);
    fold.b = to_page(fold.b);
    placed.folds.push_back(fold);
  }
  for (const PieceTab& pieceTab : piece.tabs) {
    Tab tab;
    tab.label = pieceTab.label;
    for (int f : pieceTab.flaps) {
      const Flap& flap = piece.flaps[f];
      std::vector<Vec2> polygon, base;
      for (auto it = flap.base.rbegin(); it != flap.base.rend(); ++it)
        polygon.push_back(to_page(*it));
      for (const Vec2& q : flap.outer) polygon.push_back(to_page(q));
      for (const Vec2& p : flap.base) base.push_back(to_page(p));
      tab.flaps.push_back(std::move(polygon));
      tab.bases.push_back(std::move(base));
      for (TexturePatch patch : flap.texture) {
        for (Vec2& corner : patch.corners) corner = to_page(corner);
        for (Vec2& point : patch.clip) point = to_page(point);
        tab.texture.push_back(std::move(patch));
      }
    }
    placed.tabs.push_back(std::move(tab));
  }
  for (const auto& mark : piece.marks)
    for (const auto& part : clear_of_text({FoldLine{mark[0], mark[1]}}, boxes))
      placed.marks.push_back({to_page(part.a), to_page(part.b)});
  for (const PieceLabel& label : piece.labels) {
    std::vector<Vec2> leader;
    for (const Vec2& p : label.leader) leader.push_back(to_page(p));
    placed.labels.push_back({label.text, to_page(label.position),
                             direction_degrees(label.direction), label.size, label.outside,
                             std::move(leader)});
  }
  const PieceLabel number = piece.number ? *piece.number : piece_number(data, piece, box, options);
  placed.number = {number.text, to_page(number.position), direction_degrees(number.direction),
                   number.size, number.outside, {}};
  return placed;
}

void add_page_furniture(Page& page, int index, int count, const LayoutOptions& options,
                        double mm_per_unit) {
  const double bottom = options.page.height_mm - options.margin_mm;
  const double width = options.page.width_mm - 2 * options.margin_mm;
  const double text = std::min(3.0, 0.4 * options.footer_mm);
  page.footer.text = "page " + std::to_string(index + 1) + " / " + std::to_string(count);
  page.footer.size_mm = text;
  const double footer_width = 0.6 * text * static_cast<double>(page.footer.text.size());
  page.footer.position = Vec2(options.page.width_mm - options.margin_mm - 0.5 * footer_width,
                              bottom - 0.5 * options.footer_mm);
  ScaleBar& bar = page.scale_bar;
  if (options.footer_mm <= 0) {
    bar.length_mm = 0;
    page.footer.text.clear();
    return;
  }
  bar.length_mm = 10;
  for (double length : {20.0, 50.0, 100.0})
    if (length <= width / 3) bar.length_mm = length;
  bar.tick_spacing_mm = bar.length_mm / 5;
  bar.tick_height_mm = std::min(2.0, 0.3 * options.footer_mm);
  bar.start = Vec2(options.margin_mm, bottom - 0.5 * (options.footer_mm - bar.tick_height_mm));
  bar.caption.text =
      format_mm(bar.length_mm) + " mm (1 model unit = " + format_number(mm_per_unit, 4) + " mm)";
  bar.caption.size_mm = text;
  const double caption_width = 0.6 * text * static_cast<double>(bar.caption.text.size());
  bar.caption.position = Vec2(options.margin_mm + bar.length_mm + 3 + 0.5 * caption_width,
                              bottom - 0.5 * options.footer_mm);
}

LayoutStats layout_stats(const PatternLayout& layout, const Vec2& area) {
  LayoutStats stats;
  std::map<std::string, bool> tabbed;
  stats.smallest_text_mm = std::numeric_limits<double>::infinity();
  bool any_text = false;
  for (const Page& page : layout.pages) {
    double covered = 0;
    std::vector<std::array<Vec2, 4>> boxes;  // texts of one page only can overlap
    for (const auto* pieces : {&page.pieces, &page.joints}) {
      for (const PlacedPiece& piece : *pieces) {
        for (const Triangle& t : piece.triangles)
          covered += 0.5 * std::abs(cross(piece.vertices[t[1]] - piece.vertices[t[0]],
                                          piece.vertices[t[2]] - piece.vertices[t[0]]));
        for (const Tab& tab : piece.tabs)
          for (const auto& flap : tab.flaps) covered += std::abs(signed_area(flap));
        for (const PieceSeam& seam : piece.seams)
          tabbed[seam.label] = tabbed[seam.label] || seam.tab;
        if (pieces == &page.joints) {
          tabbed[piece.name] = true;
          ++stats.joining_strips;
        }
        std::vector<const Label*> texts{&piece.number};
        for (const Label& label : piece.labels) texts.push_back(&label);
        for (const Label* text : texts) {
          stats.smallest_text_mm = std::min(stats.smallest_text_mm, text->size_mm);
          any_text = true;
          boxes.push_back(label_box(*text));
        }
      }
    }
    stats.page_fill.push_back(area.prod() > 0 ? covered / area.prod() : 0.0);
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        if (convex_overlap(boxes[i].data(), 4, boxes[j].data(), 4, 0.0)) ++stats.overlapping_text;
  }
  if (!any_text) stats.smallest_text_mm = 0.0;
  stats.seams = static_cast<int>(tabbed.size());
  for (const auto& [label, tab] : tabbed) stats.seams_without_tab += tab ? 0 : 1;
  return stats;
}

// A joining strip for a seam `length` mm long: a rectangle (length + 2 mm, at least 8 mm) by
// 2 x tab_width_mm, flat, cut all round (model units at mm_per_unit); its centre line is where
// the seam goes.
FlatStrip joining_strip(int id, double length, const LayoutOptions& options, double mm_per_unit) {
  const double l = std::max(length + 2.0, 8.0) / mm_per_unit;
  const double w = 2.0 * options.tab_width_mm / mm_per_unit;
  FlatStrip strip;
  strip.id = id;
  strip.source_strip = -1;
  strip.vertices2d = {Vec2(0, 0), Vec2(l, 0), Vec2(l, w), Vec2(0, w)};
  for (const Vec2& v : strip.vertices2d) strip.vertices3d.emplace_back(v.x(), v.y(), 0.0);
  strip.triangles = {{0, 1, 2}, {0, 2, 3}};
  for (int i = 0; i < 4; ++i) strip.boundary.push_back({i, (i + 1) % 4, EdgeKind::Cut, -1, "", -1});
  return strip;
}

}  // namespace

std::vector<int> strips_exceeding_page(const std::vector<FlatStrip>& strips,
                                       const LayoutOptions& options) {
  Prepared p = prepare(strips, options);
  std::vector<int> ids;
  for (const StripData& data : p.strips)
    if (!data.triangles.empty() && !strip_fits(data, p)) ids.push_back(data.strip->id);
  return ids;
}

namespace {

// A strip that packs badly: longer than half the page's long side and thin or bent (its area
// under 40% of its box, or the box over 3 times as long as wide). One larger than the page
// counts too: split only to fit the page, its parts stay as long and bent.
bool long_and_thin(const StripData& data, const Prepared& p, double* waste) {
  const double w = p.area.x() - 2 * p.reserve, h = p.area.y() - 2 * p.reserve;
  bool fits = false;
  const OrientedBox box = tightest_box(convex_hull(piece_points(data, data.triangles)), w, h, &fits);
  double area = 0.0;
  for (const int t : data.triangles) {
    const Triangle& tri = data.strip->triangles[t];
    area += 0.5 * std::abs(cross(data.points[tri[1]] - data.points[tri[0]],
                                 data.points[tri[2]] - data.points[tri[0]]));
  }
  const double length = box.size.maxCoeff(), width = box.size.minCoeff();
  *waste = box.size.prod() - area;
  return length > 0.5 * std::max(w, h) &&
         (area < 0.4 * box.size.prod() || length > 3.0 * width);
}

struct LongStrips {
  int found = 0;     // strips that fit the page but are long and thin
  int oversize = 0;  // strips larger than the page, long and thin
  int split = 0;     // of those split_long covers, split in parts of half a page
  std::vector<std::pair<double, int>> waste;  // of each long thin strip: box minus area, index
};

// Which long and thin strips a layout splits in parts of half a page (Fitting: those that fit
// the page; All: every one), or splits where they bend (Bends: every one; a part that still
// fits no page is then split to fit it).
enum class SplitLong { None, Fitting, All, Bends };

// The layout, long and thin strips split as `split_long` says (of them only those `chosen`
// marks by strip index, where given); *long_strips counts them. `divided`: the strips' triangles
// were divided (StripData::divided).
PatternLayout layout_with(const std::vector<FlatStrip>& strips, const LayoutOptions& options,
                          SplitLong split_long, LongStrips* long_strips,
                          const std::vector<char>* chosen = nullptr, LabelCache* labels = nullptr,
                          bool divided = false);

}  // namespace

namespace {

// The tries of layout_pages on strips as they are (see there).
PatternLayout layout_tries(const std::vector<FlatStrip>& strips, const LayoutOptions& options,
                           bool divided) {
  LongStrips whole;
  // The pieces the tries share (most of them) get their labels arranged once.
  LabelCache labels;
  PatternLayout layout =
      layout_with(strips, options, SplitLong::None, &whole, nullptr, &labels, divided);
  // No long thin strip is found unless nesting with split_long_strips.
  if (layout.pages.size() < 2 || whole.found + whole.oversize == 0) return layout;
  // Laid out again with the long thin strips that fit split in half pages, then also those
  // larger than the page (split only to fit it their parts would stay long and bent), then
  // with them split where they bend; each kept where every page it saves against the best so
  // far costs at most splits_per_page more pieces.
  // Pieces printed of the model (joining strips apart).
  auto pieces_of = [](const PatternLayout& l) {
    int count = 0;
    for (const Page& page : l.pages) count += static_cast<int>(page.pieces.size());
    return count;
  };
  PatternLayout best = std::move(layout);
  const std::size_t unsplit_pages = best.pages.size();
  const int unsplit_pieces = pieces_of(best);
  int best_added = 0;
  bool kept = false, bends = false;
  // Kept where every page it saves against the best so far costs at most splits_per_page more
  // pieces; says whether it saved pages at too high a cost.
  auto too_costly = [&](SplitLong mode, const std::vector<char>* chosen) {
    LongStrips parts;
    PatternLayout halves = layout_with(strips, options, mode, &parts, chosen, &labels, divided);
    const int saved = static_cast<int>(best.pages.size()) - static_cast<int>(halves.pages.size());
    const int added = pieces_of(halves) - unsplit_pieces;
    if (parts.split == 0 || saved <= 0) return false;
    if (added - best_added > options.splits_per_page * saved) return true;
    best = std::move(halves);
    best_added = added;
    kept = true;
    bends = mode == SplitLong::Bends;
    return false;
  };
  if (whole.found > 0) too_costly(SplitLong::Fitting, nullptr);
  if (whole.oversize > 0) too_costly(SplitLong::All, nullptr);
  // Split where they bend: every long thin strip, then (where that saves pages, but too few
  // for the pieces it adds) only the half, the quarter, the eighth of them that waste the most
  // paper round them, till one is kept.
  if (too_costly(SplitLong::Bends, nullptr)) {
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
      if (!too_costly(SplitLong::Bends, &chosen)) break;
    }
  }
  if (kept) {
    const int count = std::abs(best_added);
    best.warnings.push_back(
        "long thin strips" +
        std::string(bends ? " split where they bend" : " split in parts of half a page") +
        " make " + std::to_string(count) + (best_added < 0 ? " fewer " : " more ") +
        (count == 1 ? "piece" : "pieces") + ", which saves " +
        std::to_string(unsplit_pages - best.pages.size()) + " of " + std::to_string(unsplit_pages) +
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
  const Prepared p = prepare(strips, options);
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
  PatternLayout layout = layout_tries(strips, options, false);
  const int n = divisions(strips, options);
  if (n <= 1) return layout;
  // A strip no page holds, of triangles too large to cut it well at their edges: laid out
  // again with every triangle divided (the same surface), kept where that saves pages.
  PatternLayout divided = layout_tries(divide_triangles(strips, n), options, true);
  // Kept where fewer pieces overflow their page, or as many and every page it saves costs at
  // most splits_per_page more pieces (as for the long thin strips).
  auto overflowing = [](const PatternLayout& l) {
    return std::count_if(l.warnings.begin(), l.warnings.end(), [](const std::string& note) {
      return note.find(" overflows its page") != std::string::npos;
    });
  };
  auto pieces_of = [](const PatternLayout& l) {
    long count = 0;
    for (const Page& page : l.pages) count += static_cast<long>(page.pieces.size());
    return count;
  };
  const auto over = overflowing(layout), over_divided = overflowing(divided);
  const long saved =
      static_cast<long>(layout.pages.size()) - static_cast<long>(divided.pages.size());
  const long added = pieces_of(divided) - pieces_of(layout);
  if (!(over_divided < over ||
        (over_divided == over && saved > 0 && added <= options.splits_per_page * saved)))
    return layout;
  std::unordered_map<int, std::size_t> vertices;  // strip id -> its vertex count
  for (const FlatStrip& strip : strips) vertices[strip.id] = strip.vertices3d.size();
  for (Page& page : divided.pages)
    for (PlacedPiece& piece : page.pieces) {
      const auto it = vertices.find(piece.strip_id);
      for (int& v : piece.strip_vertex)
        if (it == vertices.end() || v >= static_cast<int>(it->second)) v = -1;
    }
  divided.warnings.push_back(
      "triangles divided in " + std::to_string(n * n) +
      " to cut strips larger than a page across them: " + std::to_string(divided.pages.size()) +
      " pages instead of " + std::to_string(layout.pages.size()) +
      (over > over_divided
           ? ", and " + std::to_string(over - over_divided) + " fewer pieces overflow their page"
           : ""));
  return divided;
}

}  // namespace

PatternLayout layout_pages(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  PatternLayout layout = front_layout(strips, options);
  if (options.print_side == PrintSide::Back) mirror_for_back_printing(layout);
  return layout;
}

namespace {

PatternLayout layout_with(const std::vector<FlatStrip>& strips, const LayoutOptions& options,
                          SplitLong split_long, LongStrips* long_strips,
                          const std::vector<char>* chosen, LabelCache* labels, bool divided) {
  *long_strips = LongStrips();
  Prepared p = prepare(strips, options);
  for (StripData& data : p.strips) data.divided = divided;
  PatternLayout layout;
  layout.page = options.page;
  layout.margin_mm = options.margin_mm;
  layout.mm_per_unit = p.mm_per_unit;
  std::vector<std::string>& warnings = layout.warnings;

  std::set<std::string> used_labels;
  for (const FlatStrip& strip : strips)
    for (const BoundaryEdge& e : strip.boundary)
      if (e.kind == EdgeKind::Seam) used_labels.insert(e.label);

  std::vector<Piece> pieces;
  int number = 0;  // pieces are numbered 1..N in strip order, with no gaps
  for (int s = 0; s < static_cast<int>(p.strips.size()); ++s) {
    StripData& data = p.strips[s];
    if (data.triangles.empty()) {
      warnings.push_back(strip_name(*data.strip) + " has no triangles; skipped");
      continue;
    }
    ++number;
    std::vector<std::vector<int>> sets;
    const bool fits = strip_fits(data, p);
    double waste = 0.0;
    bool long_thin = options.packing == PackingMethod::Nest && options.split_long_strips &&
                     long_and_thin(data, p, &waste);
    (fits ? long_strips->found : long_strips->oversize) += long_thin;
    if (long_thin) long_strips->waste.push_back({waste, s});
    if (chosen && !(*chosen)[s]) long_thin = false;
    const double w = p.area.x() - 2 * p.reserve, h = p.area.y() - 2 * p.reserve;
    if (long_thin && split_long == SplitLong::Bends) {
      for (std::vector<int>& part : split_at_bends(data, used_labels)) {
        if (strip_fits(data, p, part)) {
          sets.push_back(std::move(part));
          continue;
        }
        for (std::vector<int>& piece : split_to_fit(data, part, w, h, used_labels))
          sets.push_back(std::move(piece));
      }
      long_strips->split += sets.size() > 1;
    } else if (long_thin &&
               (split_long == SplitLong::All || (split_long == SplitLong::Fitting && fits))) {
      // Half the page: its long side halved.
      sets = h >= w ? split_to_fit(data, w, 0.5 * h, used_labels)
                    : split_to_fit(data, 0.5 * w, h, used_labels);
      long_strips->split += sets.size() > 1;
    } else if (fits) {
      sets.push_back(data.triangles);
    } else {
      sets = split_to_fit(data, w, h, used_labels);
    }
    if (!fits) {
      bool unused = false;
      const OrientedBox box =
          tightest_box(convex_hull(piece_points(data, data.triangles)), w, h, &unused);
      warnings.push_back(strip_name(*data.strip) + " (" + format_mm(box.size.x()) + " x " +
                         format_mm(box.size.y()) +
                         " mm) fits no page orientation with room "
                         "for tabs (" +
                         format_mm(w) + " x " + format_mm(h) + " mm); split into " +
                         std::to_string(sets.size()) + " pieces at inner edges");
    }
    for (int k = 0; k < static_cast<int>(sets.size()); ++k) {
      Piece piece;
      piece.strip = s;
      piece.index = k;
      piece.count = static_cast<int>(sets.size());
      piece.name = piece_name(number, k, piece.count);
      piece.triangles = std::move(sets[k]);
      piece.loops = piece_loops(data, piece.triangles, warnings);
      pieces.push_back(std::move(piece));
    }
  }

  const SeamEdges seams = match_seam_edges(pieces, p.strips);
  const std::vector<Chain> chains = seam_chains(pieces, p.strips, seams, p.tolerance3d);
  const std::vector<SeamPair> pairs = pair_chains(chains, seams, pieces, p.tolerance3d, warnings);
  for (const SeamPair& pair : pairs) {
    for (int side : {pair.first, pair.second}) {
      if (side < 0) continue;
      const Chain& chain = chains[side];
      Piece& piece = pieces[chain.piece];
      auto& loop = piece.loops[chain.loop];
      for (int i = 0; i < chain.count; ++i)
        loop[(chain.start + i) % loop.size()].printed = pair.printed;
      piece.labels.push_back(
          chain_label(p.strips[piece.strip], piece, chain, pair.printed, options.label_size_mm));
      piece.labels.back().chain = side;
      add_alignment_marks(p.strips[piece.strip], piece, chain, options.alignment_mark_mm);
    }
  }
  const bool tabs = options.tab_width_mm > 0 && options.tab_style != TabStyle::None;
  if (tabs) add_tabs(pieces, p.strips, chains, pairs, seams, options, warnings);
  for (const SeamPair& pair : pairs) {
    const int a = chains[pair.first].piece;
    const int b = pair.second >= 0 ? chains[pair.second].piece : -1;
    auto has_tab = [&](int piece) {
      for (const PieceTab& tab : pieces[piece].tabs)
        if (tab.label == pair.printed && !tab.flaps.empty()) return true;
      return false;
    };
    pieces[a].seams.push_back({pair.printed, b >= 0 ? pieces[b].name : "", has_tab(a)});
    if (b >= 0) pieces[b].seams.push_back({pair.printed, pieces[a].name, has_tab(b)});
  }
  // Seams with room for a tab on neither side are glued with a joining strip behind them.
  std::deque<FlatStrip> joint_strips;  // the strips' storage (StripData points into it)
  if (options.joining_strips && tabs) {
    int next_id = 0;
    for (const FlatStrip& strip : strips) next_id = std::max(next_id, strip.id + 1);
    const std::size_t model_pieces = pieces.size();
    for (const SeamPair& pair : pairs) {
      if (pair.second < 0) continue;
      const Chain& chain = chains[pair.first];
      bool tabbed = false;
      for (int side : {pair.first, pair.second})
        for (const PieceTab& tab : pieces[chains[side].piece].tabs)
          tabbed = tabbed || (tab.label == pair.printed && !tab.flaps.empty());
      if (tabbed) continue;
      const Piece& owner = pieces[chain.piece];
      const double length = chain_length(p.strips[owner.strip], owner, chain);
      joint_strips.push_back(joining_strip(next_id++, length, options, p.mm_per_unit));
      p.strips.push_back(prepare_strip(joint_strips.back(), p.mm_per_unit));
      StripData& data = p.strips.back();
      Piece joint;
      joint.strip = static_cast<int>(p.strips.size()) - 1;
      joint.name = pair.printed;
      joint.joint = true;
      joint.triangles = data.triangles;
      joint.loops = piece_loops(data, joint.triangles, warnings);
      const Vec2 a = 0.5 * (data.points[0] + data.points[3]);
      const Vec2 b = 0.5 * (data.points[1] + data.points[2]);
      joint.marks.push_back({a + Vec2(0.5, 0), b - Vec2(0.5, 0)});
      pieces.push_back(std::move(joint));
    }
    if (pieces.size() > model_pieces)
      warnings.push_back(std::to_string(pieces.size() - model_pieces) +
                         " seams with no room for a tab get a joining strip glued behind them");
  }

  std::vector<Orientation> orientations;
  std::vector<int> packed, oversized;
  std::vector<Vec2> sizes;
  for (int i = 0; i < static_cast<int>(pieces.size()); ++i) {
    orientations.push_back(orient_piece(p.strips[pieces[i].strip], pieces[i], p.area));
    arrange_labels(p.strips[pieces[i].strip], pieces[i], chains, orientations.back().box, options,
                   warnings, labels);
    if (pieces[i].joint && pieces[i].number) {
      // The seam's label at the middle of its joining strip, on the centre line.
      const auto& points = p.strips[pieces[i].strip].points;
      PieceLabel& name = *pieces[i].number;
      name.position = 0.25 * (points[0] + points[1] + points[2] + points[3]);
      name.direction = Vec2::UnitX();
      name.size = std::max(options.min_text_mm,
                           std::min(options.number_size_mm, 0.6 * (points[2] - points[1]).norm()));
      name.outside = false;
    }
    // Text printed beside the piece takes paper too.
    if (!outside_text(pieces[i]).empty())
      orientations.back() = orient_piece(p.strips[pieces[i].strip], pieces[i], p.area);
    const Orientation& o = orientations.back();
    if (o.fits && o.box.size.minCoeff() > 0) {
      packed.push_back(i);
      sizes.push_back(o.box.size);
    } else {
      oversized.push_back(i);
      if (!o.fits)
        warnings.push_back("piece " + pieces[i].name + " (" + format_mm(o.box.size.x()) + " x " +
                           format_mm(o.box.size.y()) +
                           " mm with tabs) does not fit the printable area (" +
                           format_mm(p.area.x()) + " x " + format_mm(p.area.y()) +
                           " mm) and overflows its page: lower height_mm or use a larger page");
    }
  }
  const PackingMethod rectangles =
      options.packing == PackingMethod::Nest ? PackingMethod::MaxRects : options.packing;
  const PackResult result =
      pack_with_spacing(sizes, p.area.x(), p.area.y(), options.spacing_mm, rectangles);
  layout.shelf_page_count = (rectangles == PackingMethod::Shelf
                                 ? result.pages
                                 : pack_with_spacing(sizes, p.area.x(), p.area.y(),
                                                     options.spacing_mm, PackingMethod::Shelf)
                                       .pages) +
                            static_cast<int>(oversized.size());
  layout.rectangle_page_count = result.pages + static_cast<int>(oversized.size());
  // Nesting by outlines; kept only where it needs no more pages than the rectangles.
  std::vector<NestPlacement> nested;
  int nested_pages = 0;
  if (options.packing == PackingMethod::Nest && !packed.empty()) {
    std::vector<NestShape> shapes;
    for (const int i : packed) {
      const StripData& data = p.strips[pieces[i].strip];
      NestShape shape;
      for (const int t : pieces[i].triangles) {
        const Triangle& tri = data.strip->triangles[t];
        shape.convex.push_back({data.points[tri[0]], data.points[tri[1]], data.points[tri[2]]});
      }
      for (const Flap& flap : pieces[i].flaps) {
        std::vector<Vec2> outline(flap.base.begin(), flap.base.end());
        outline.insert(outline.end(), flap.outer.begin(), flap.outer.end());
        shape.convex.push_back(convex_hull(outline));
      }
      for (const auto& mark : pieces[i].marks) shape.convex.push_back({mark[0], mark[1]});
      for (const auto& box : outside_text(pieces[i]))
        shape.convex.push_back(std::vector<Vec2>(box.begin(), box.end()));
      shapes.push_back(std::move(shape));
    }
    NestOptions nest;
    nest.spacing_mm = options.spacing_mm;
    nest.rotations = options.nest_rotations;
    nest.cell_mm = options.nest_cell_mm;
    nest.repacks = options.nest_repacks;
    std::vector<int> shape_of(pieces.size(), -1);
    for (std::size_t k = 0; k < packed.size(); ++k) shape_of[packed[k]] = static_cast<int>(k);
    for (const SeamPair& pair : pairs) {
      if (pair.second < 0) continue;
      const int a = shape_of[chains[pair.first].piece], b = shape_of[chains[pair.second].piece];
      if (a >= 0 && b >= 0 && a != b) nest.neighbours.push_back({a, b});
    }
    nested = nest_shapes(shapes, p.area, nest, &nested_pages);
    const bool complete = std::all_of(nested.begin(), nested.end(),
                                      [](const NestPlacement& n) { return n.page >= 0; });
    if (!complete || nested_pages > result.pages) nested.clear();
  }
  const int packed_pages = nested.empty() ? result.pages : nested_pages;
  layout.pages.resize(packed_pages + oversized.size());
  // A placed piece onto its page; a joining strip among the page's joints, of no model strip.
  auto put = [&](int page, int i, PlacedPiece placed) {
    if (!pieces[i].joint) {
      layout.pages[page].pieces.push_back(std::move(placed));
      return;
    }
    placed.strip_id = -1;
    layout.pages[page].joints.push_back(std::move(placed));
  };
  for (std::size_t k = 0; k < packed.size(); ++k) {
    const int i = packed[k];
    if (!nested.empty()) {
      const NestPlacement& at = nested[k];
      put(at.page, i, place_piece_at(
          p.strips[pieces[i].strip], pieces[i], orientations[i].box, at.angle,
          at.offset + Vec2(options.margin_mm, options.margin_mm), options, p.mm_per_unit));
      continue;
    }
    const PackedRectangle& at = result.placements[k];
    put(at.page, i, place_piece(
        p.strips[pieces[i].strip], pieces[i], orientations[i].box, at, options, p.mm_per_unit));
  }
  for (std::size_t k = 0; k < oversized.size(); ++k) {
    const int i = oversized[k];
    put(packed_pages + static_cast<int>(k), i, place_piece(p.strips[pieces[i].strip], pieces[i], orientations[i].box, {0, 0, 0, false},
                    options, p.mm_per_unit));
  }
  for (int i = 0; i < static_cast<int>(layout.pages.size()); ++i)
    add_page_furniture(layout.pages[i], i, static_cast<int>(layout.pages.size()), options,
                       p.mm_per_unit);
  layout.stats = layout_stats(layout, p.area);
  return layout;
}

}  // namespace

}  // namespace papercraft
