// A piece put on its page (the strip frame turned into page millimetres), the page's footer
// and scale bar, and the layout's statistics.
#include "nodes/layout/place_piece.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <unordered_map>

#include "nodes/layout/annotations.h"
#include "nodes/layout/format_mm.h"
#include "nodes/layout/pages.h"

namespace papercraft::layout_internal {
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

}  // namespace

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
      placed.edges.push_back({a, b, e.kind, e.printed, e.flap >= 0 || !e.edge_flaps.empty()});
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
                   number.size, number.outside,           {}};
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

}  // namespace papercraft::layout_internal
