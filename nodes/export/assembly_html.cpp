#include "nodes/export/assembly_html.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>

#include "core/printable_utf8.h"
#include "nodes/export/assembly_template.h"
#include "nodes/export/base64.h"
#include "nodes/export/gzip.h"
#include "nodes/export/piece_colour.h"
#include "nodes/export/piece_points3d.h"
#include "nodes/export/svg.h"

namespace papercraft {

namespace {

long fixed(double value, double per_unit) {
  return std::lround(value * per_unit);
}

// The vertex of `piece` at page point `p`: the one with these very coordinates (edges are
// made from the vertices), else the nearest.
int vertex_at(const PlacedPiece& piece, const std::map<std::pair<double, double>, int>& index,
              const Vec2& p) {
  const auto found = index.find({p.x(), p.y()});
  if (found != index.end()) return found->second;
  int nearest = 0;
  for (int i = 1; i < static_cast<int>(piece.vertices.size()); ++i)
    if ((piece.vertices[i] - p).squaredNorm() < (piece.vertices[nearest] - p).squaredNorm())
      nearest = i;
  return nearest;
}

// Each seam label of the piece once: the piece across, its edges (point index pairs) and
// where its labels are printed.
nlohmann::json seams_data(const PlacedPiece& piece) {
  std::map<std::pair<double, double>, int> index;
  for (int i = 0; i < static_cast<int>(piece.vertices.size()); ++i)
    index.emplace(std::make_pair(piece.vertices[i].x(), piece.vertices[i].y()), i);
  nlohmann::json seams = nlohmann::json::array();
  std::set<std::string> seen;
  for (const PieceSeam& seam : piece.seams) {
    if (seam.label.empty() || !seen.insert(seam.label).second) continue;
    nlohmann::json edges = nlohmann::json::array();
    for (const PlacedEdge& edge : piece.edges)
      if (edge.kind == EdgeKind::Seam && edge.label == seam.label && !piece.vertices.empty()) {
        edges.push_back(vertex_at(piece, index, edge.a));
        edges.push_back(vertex_at(piece, index, edge.b));
      }
    nlohmann::json boxes = nlohmann::json::array();
    for (const Label& label : piece.labels)
      if (label.text == seam.label)
        boxes.push_back({fixed(label.position.x(), 10), fixed(label.position.y(), 10),
                         std::round(label.angle_degrees * 10) / 10, fixed(label.size_mm, 10)});
    seams.push_back({{"label", seam.label},
                     {"partner", seam.partner},
                     {"edges", std::move(edges)},
                     {"boxes", std::move(boxes)}});
  }
  return seams;
}

// The grid the pieces' 3D points are written on: 65,536 steps over the model's largest side
// (3 µm for a model 200 mm tall), from the corner of its bounding box.
struct PointGrid {
  Vec3 origin = Vec3::Zero();
  double step = 1.0;
};

PointGrid point_grid(const std::vector<std::vector<Vec3>>& points) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& piece : points)
    for (const Vec3& p : piece) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (!(lo.array() <= hi.array()).all()) return {};
  const double extent = (hi - lo).maxCoeff();
  return {lo, extent > 0 ? extent / 65535.0 : 1.0};
}

// Little-endian unsigned integers of `bytes` bytes each, in base64.
std::string packed(const std::vector<std::uint32_t>& values, int bytes) {
  std::string raw;
  raw.reserve(values.size() * bytes);
  for (std::uint32_t value : values)
    for (int k = 0; k < bytes; ++k) raw += static_cast<char>((value >> (8 * k)) & 0xff);
  return base64(raw);
}

nlohmann::json piece_data(const PlacedPiece& piece, const std::vector<Vec3>& points_mm,
                          const PointGrid& grid, int page, const BuildStep* step,
                          const std::string& colour) {
  std::vector<std::uint32_t> points;
  for (const Vec3& p : points_mm)
    for (int k = 0; k < 3; ++k)
      points.push_back(static_cast<std::uint32_t>(
          std::clamp(std::lround((p[k] - grid.origin[k]) / grid.step), 0L, 65535L)));
  std::vector<std::uint32_t> triangles;
  for (const Triangle& t : piece.triangles)
    for (int k = 0; k < 3; ++k) triangles.push_back(static_cast<std::uint32_t>(t[k]));
  const int index_bytes = points_mm.size() <= 65536 ? 2 : 4;
  nlohmann::json outline = nlohmann::json::array();
  for (const auto& loop : piece.outline) {
    nlohmann::json flat = nlohmann::json::array();
    for (const Vec2& p : loop) {
      flat.push_back(fixed(p.x(), 10));
      flat.push_back(fixed(p.y(), 10));
    }
    outline.push_back(std::move(flat));
  }
  return {{"name", piece.name},
          {"page", page},
          {"step", step ? step->step : 0},
          {"part", step ? step->part : 0},
          {"colour", colour},
          {"points", packed(points, 2)},
          {"triangles", packed(triangles, index_bytes)},
          {"index_bytes", index_bytes},
          {"outline", std::move(outline)},
          {"number", {fixed(piece.number.position.x(), 10), fixed(piece.number.position.y(), 10)}},
          {"seams", seams_data(piece)}};
}

// The pieces in page order, each in the colour the printed guide gives it, and the grid of
// their 3D points.
std::pair<nlohmann::json, PointGrid> pieces_data(const PatternLayout& layout,
                                                 const std::vector<FlatStrip>& strips,
                                                 const BuildOrder& order) {
  std::map<int, const FlatStrip*> by_id;
  for (const FlatStrip& strip : strips) by_id[strip.id] = &strip;
  struct Placed {
    const PlacedPiece* piece;
    int page;
  };
  std::vector<Placed> placed;
  std::vector<std::vector<Vec3>> points;
  for (std::size_t page = 0; page < layout.pages.size(); ++page)
    for (const PlacedPiece& piece : layout.pages[page].pieces) {
      const auto strip = by_id.find(piece.strip_id);
      if (strip == by_id.end()) continue;
      std::vector<Vec3> mm = piece_points3d(piece, *strip->second);
      for (Vec3& p : mm) p *= layout.mm_per_unit;
      placed.push_back({&piece, static_cast<int>(page) + 1});
      points.push_back(std::move(mm));
    }
  const PointGrid grid = point_grid(points);
  nlohmann::json pieces = nlohmann::json::array();
  for (std::size_t i = 0; i < placed.size(); ++i)
    pieces.push_back(piece_data(*placed[i].piece, points[i], grid, placed[i].page,
                                order.step_of(placed[i].piece->name),
                                hex_colour(piece_colour(static_cast<int>(i)))));
  return {std::move(pieces), grid};
}

nlohmann::json steps_data(const BuildOrder& order) {
  nlohmann::json steps = nlohmann::json::array();
  for (const BuildStep& step : order.steps) {
    nlohmann::json labels = nlohmann::json::array();
    for (const GlueSeam& seam : step.seams) labels.push_back(seam.label);
    steps.push_back(
        {{"piece", step.piece}, {"text", build_step_text(step)}, {"seams", std::move(labels)}});
  }
  return steps;
}

// The data as the page carries it: its JSON (UTF-8; bytes that are not become U+FFFD),
// gzip-compressed, in base64, which nothing in it can end the <script> it stands in.
std::string page_data(const nlohmann::json& data) {
  return base64(gzip(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
}

std::string filled_template(const std::string& title, const std::string& data) {
  const std::string_view page = assembly_page_template();
  const std::string_view title_mark = "@PAPERCRAFT_TITLE@", data_mark = "@PAPERCRAFT_DATA@";
  const std::size_t at_title = page.find(title_mark), at_data = page.find(data_mark);
  std::string out;
  out.reserve(page.size() + title.size() + data.size());
  out += page.substr(0, at_title);
  out += title;
  out += page.substr(at_title + title_mark.size(), at_data - at_title - title_mark.size());
  out += data;
  out += page.substr(at_data + data_mark.size());
  return out;
}

std::vector<std::string> svg_pages(const PatternLayout& layout, const StyleOptions& style) {
  std::vector<std::string> pages;
  for (int page = 0; page < static_cast<int>(layout.pages.size()); ++page)
    pages.push_back(pattern_page_svg(layout, page, style));
  return pages;
}

std::string megabytes(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}

}  // namespace

AssemblyHtml assembly_html(const PatternLayout& layout, const std::vector<FlatStrip>& strips,
                           const BuildOrder& order, const StyleOptions& style,
                           const AssemblyHtmlOptions& options) {
  const std::string name = printable_utf8(style.title.empty() ? "model" : style.title);
  nlohmann::json data = {
      {"name", name},
      {"version", PAPERCRAFT_VERSION},
      {"page", {{"width_mm", layout.page.width_mm}, {"height_mm", layout.page.height_mm}}},
      {"page_count", layout.pages.size()},
      {"parts", order.parts},
      {"notes", nlohmann::json::array()},
      {"pages_svg", nlohmann::json::array()},
      {"steps", steps_data(order)}};
  auto [pieces, grid] = pieces_data(layout, strips, order);
  data["pieces"] = std::move(pieces);
  data["grid"] = {{"origin", {grid.origin.x(), grid.origin.y(), grid.origin.z()}},
                  {"step", grid.step}};
  const std::string title = xml_escaped(name) + ": assembly";
  AssemblyHtml result;
  auto page_with = [&](const std::vector<std::string>& pages) {
    data["pages_svg"] = pages;
    data["notes"] = result.notes;
    return filled_template(title, page_data(data));
  };
  StyleOptions page_style = style;
  page_style.svg_decimals = options.svg_decimals;
  result.text = page_with(svg_pages(layout, page_style));
  if (result.text.size() <= options.max_bytes) return result;
  const std::string limit = megabytes(options.max_bytes);
  if (page_style.images) {
    page_style.images = nullptr;
    result.notes.push_back(
        "The pieces' print images are left out of the pages shown here, to "
        "keep this file under " +
        limit + "; pattern.pdf has them.");
    result.text = page_with(svg_pages(layout, page_style));
    if (result.text.size() <= options.max_bytes) return result;
    result.notes.pop_back();
  }
  result.notes.push_back("The pattern pages are left out of this file to keep it under " + limit +
                         ": the pieces are drawn by their outlines; print pattern.pdf.");
  result.text = page_with({});
  if (result.text.size() > options.max_bytes) {
    result.notes.push_back("This file is " + megabytes(result.text.size()) + ", over " + limit +
                           ", with the model's 3D pieces alone.");
    result.text = page_with({});
  }
  return result;
}

}  // namespace papercraft
