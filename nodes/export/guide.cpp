#include "nodes/export/guide.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>

#include "core/errors.h"
#include "nodes/export/image.h"
#include "nodes/export/piece_colour.h"
#include "nodes/export/piece_points3d.h"

namespace papercraft {
namespace {

struct View {
  std::string name;
  Vec3 toward;  // from the model towards the viewer
  Vec3 up;
};

std::array<Vec3, 3> view_axes(const View& view) {
  const Vec3 depth = view.toward.normalized();
  Vec3 right = view.up.cross(depth);
  if (right.norm() < 1e-9) right = Vec3::UnitX().cross(depth);
  right.normalize();
  const Vec3 up = depth.cross(right);
  return {right, up, depth};
}

void centred_text(cairo_t* cr, const std::string& text, const Vec2& at, double size) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_move_to(cr, at.x() - 0.5 * extents.x_advance, at.y() + 0.35 * size);
  cairo_show_text(cr, text.c_str());
}

// The model seen along `view` inside the box [corner, corner + size] (mm).
void draw_view(cairo_t* cr, const std::vector<GuidePiece>& pieces, const View& view,
               const Vec2& corner, const Vec2& size, double number_size) {
  const auto [right, up, depth] = view_axes(view);
  struct Face {
    std::array<Vec2, 3> points;  // projected, model units, y up
    double depth;
    double shade;
    int piece;
  };
  std::vector<Face> faces;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int p = 0; p < static_cast<int>(pieces.size()); ++p) {
    for (const auto& t : pieces[p].triangles) {
      Face face;
      double d = 0;
      for (int k = 0; k < 3; ++k) {
        face.points[k] = Vec2(t[k].dot(right), t[k].dot(up));
        lo = lo.cwiseMin(face.points[k]);
        hi = hi.cwiseMax(face.points[k]);
        d += t[k].dot(depth);
      }
      const Vec3 normal = (t[1] - t[0]).cross(t[2] - t[0]);
      if (normal.norm() == 0) continue;
      face.depth = d / 3;
      face.shade = 0.35 + 0.65 * std::abs(normal.normalized().dot(depth));
      face.piece = p;
      faces.push_back(face);
    }
  }
  if (faces.empty()) return;
  const Vec2 extent = (hi - lo).cwiseMax(Vec2::Constant(1e-12));
  const double scale = std::min((size.x() - 4) / extent.x(), (size.y() - 10) / extent.y());
  const Vec2 centre = corner + Vec2(0.5 * size.x(), 0.5 * size.y() + 3);
  auto to_page = [&](const Vec2& p) {
    const Vec2 q = (p - 0.5 * (lo + hi)) * scale;
    return Vec2(centre.x() + q.x(), centre.y() - q.y());
  };
  std::stable_sort(faces.begin(), faces.end(),
                   [](const Face& a, const Face& b) { return a.depth < b.depth; });
  // Which piece is seen where: a coarse id buffer filled in the same back-to-front order.
  constexpr double kCell = 0.5;  // mm
  const int nx = std::max(1, static_cast<int>(size.x() / kCell));
  const int ny = std::max(1, static_cast<int>(size.y() / kCell));
  std::vector<int> seen(std::size_t(nx) * ny, -1);
  for (const Face& face : faces) {
    const Rgb c = piece_colour(face.piece);
    const Vec2 a = to_page(face.points[0]), b = to_page(face.points[1]),
               d = to_page(face.points[2]);
    cairo_new_path(cr);
    cairo_move_to(cr, a.x(), a.y());
    cairo_line_to(cr, b.x(), b.y());
    cairo_line_to(cr, d.x(), d.y());
    cairo_close_path(cr);
    cairo_set_source_rgb(cr, c.r * face.shade, c.g * face.shade, c.b * face.shade);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.08);
    cairo_stroke(cr);
    const double area = (b - a).x() * (d - a).y() - (b - a).y() * (d - a).x();
    if (area == 0) continue;
    const Vec2 lo_cell = (a.cwiseMin(b).cwiseMin(d) - corner) / kCell;
    const Vec2 hi_cell = (a.cwiseMax(b).cwiseMax(d) - corner) / kCell;
    for (int y = std::max(0, int(lo_cell.y())); y <= std::min(ny - 1, int(hi_cell.y())); ++y)
      for (int x = std::max(0, int(lo_cell.x())); x <= std::min(nx - 1, int(hi_cell.x())); ++x) {
        const Vec2 p = corner + Vec2((x + 0.5) * kCell, (y + 0.5) * kCell);
        auto side = [&](const Vec2& u, const Vec2& v) {
          return ((v - u).x() * (p - u).y() - (v - u).y() * (p - u).x()) * area >= 0;
        };
        if (side(a, b) && side(b, d) && side(d, a)) seen[std::size_t(y) * nx + x] = face.piece;
      }
  }
  // Each piece's number on the visible cell of it nearest the centre of its visible cells,
  // if enough of it shows and the number stays clear of the others.
  std::map<int, std::vector<int>> cells;
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (seen[i] >= 0) cells[seen[i]].push_back(static_cast<int>(i));
  cairo_set_source_rgb(cr, 0, 0, 0);
  std::vector<std::array<double, 4>> boxes;  // numbers already drawn: x0, y0, x1, y1
  for (const auto& [piece, list] : cells) {
    const double width = 0.6 * number_size * static_cast<double>(pieces[piece].name.size());
    if (static_cast<double>(list.size()) * kCell * kCell < 1.5 * width * number_size) continue;
    Vec2 mean = Vec2::Zero();
    for (int i : list) mean += Vec2(i % nx, i / nx);
    mean /= static_cast<double>(list.size());
    int best = list.front();
    for (int i : list)
      if ((Vec2(i % nx, i / nx) - mean).squaredNorm() <
          (Vec2(best % nx, best / nx) - mean).squaredNorm())
        best = i;
    const Vec2 at = corner + Vec2((best % nx + 0.5) * kCell, (best / nx + 0.5) * kCell);
    const std::array<double, 4> box{at.x() - 0.5 * width, at.y() - 0.5 * number_size,
                                    at.x() + 0.5 * width, at.y() + 0.5 * number_size};
    bool clear = true;
    for (const auto& o : boxes)
      clear = clear && (box[2] < o[0] || o[2] < box[0] || box[3] < o[1] || o[3] < box[1]);
    if (!clear) continue;
    boxes.push_back(box);
    centred_text(cr, pieces[piece].name, at, number_size);
  }
  centred_text(cr, view.name, corner + Vec2(0.5 * size.x(), 3), 3.0);
}

}  // namespace

std::vector<GuidePiece> guide_pieces(const PatternLayout& layout,
                                     const std::vector<FlatStrip>& strips) {
  std::map<int, const FlatStrip*> by_id;
  for (const FlatStrip& strip : strips) by_id[strip.id] = &strip;
  std::vector<GuidePiece> pieces;
  for (std::size_t page = 0; page < layout.pages.size(); ++page) {
    for (const PlacedPiece& placed : layout.pages[page].pieces) {
      const auto it = by_id.find(placed.strip_id);
      if (it == by_id.end()) continue;
      GuidePiece piece;
      piece.name = placed.name;
      piece.page = static_cast<int>(page) + 1;
      const std::vector<Vec3> points = piece_points3d(placed, *it->second);
      for (const Triangle& t : placed.triangles)
        piece.triangles.push_back({points[t[0]], points[t[1]], points[t[2]]});
      pieces.push_back(std::move(piece));
    }
  }
  // Joining strips are listed in the table with their page (no 3D: not drawn in the views).
  for (std::size_t page = 0; page < layout.pages.size(); ++page)
    for (const PlacedPiece& joint : layout.pages[page].joints)
      pieces.push_back({"joint " + joint.name, static_cast<int>(page) + 1, {}});
  return pieces;
}

namespace {

constexpr double kMargin = 10.0;
constexpr double kStepTextMm = 2.6;
constexpr double kLineSpacing = 1.4;

// Front and back along the model's thinnest side (its largest outline), a side view along
// another axis, and a three-quarter view, in a 2 x 2 grid of `height` below `top`; z is up
// unless z is the thinnest side (then y).
void draw_views(cairo_t* cr, const std::vector<GuidePiece>& pieces, const PageSize& page,
                double top, double height) {
  const Vec2 cell(0.5 * (page.width_mm - 2 * kMargin), 0.5 * height);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const GuidePiece& piece : pieces)
    for (const auto& t : piece.triangles)
      for (const Vec3& v : t) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  int thin = 0;
  for (int k = 1; k < 3; ++k)
    if ((hi - lo)[k] < (hi - lo)[thin]) thin = k;
  const int up_axis = thin == 2 ? 1 : 2;
  const int other = 3 - thin - up_axis;
  const Vec3 up = Vec3::Unit(up_axis), toward = Vec3::Unit(thin), across = Vec3::Unit(other);
  const std::vector<View> views = {{"front", toward, up},
                                   {"back", -toward, up},
                                   {"side", across, up},
                                   {"three-quarter", toward + across + 0.7 * up, up}};
  const double number_size = pieces.size() > 60 ? 2.0 : 3.0;
  for (int k = 0; k < 4; ++k) {
    const Vec2 corner(kMargin + (k % 2) * cell.x(), top + (k / 2) * cell.y());
    draw_view(cr, pieces, views[k], corner, cell, number_size);
  }
}

// Which pieces each page holds, from baseline `y` on, the text shrunk (not below 2 mm) to end
// above `bottom`. Returns the baseline after the table.
double draw_page_table(cairo_t* cr, const std::vector<GuidePiece>& pieces, double y, double width,
                       double bottom) {
  std::map<int, std::vector<std::string>> on_page;
  for (const GuidePiece& piece : pieces) on_page[piece.page].push_back(piece.name);
  double text = 3.0;
  std::size_t characters = 0;
  for (const auto& [p, names] : on_page)
    for (const auto& name : names) characters += name.size() + 2;
  while (text > 2.0 && 0.6 * text * static_cast<double>(characters) / width * 1.4 * text +
                               1.4 * text * static_cast<double>(on_page.size()) >
                           bottom - y)
    text -= 0.25;
  cairo_set_font_size(cr, text);
  for (const auto& [p, names] : on_page) {
    std::string line = "page " + std::to_string(p) + ":";
    for (const std::string& name : names) {
      const std::string more = line + " " + name;
      if (0.6 * text * static_cast<double>(more.size()) > width) {
        if (y > bottom) return y;
        cairo_move_to(cr, kMargin, y);
        cairo_show_text(cr, line.c_str());
        y += 1.4 * text;
        line = "        " + name;
      } else {
        line = more;
      }
    }
    if (y > bottom) return y;
    cairo_move_to(cr, kMargin, y);
    cairo_show_text(cr, line.c_str());
    y += 1.4 * text;
  }
  return y;
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

// A step's line broken at spaces into lines no wider than `width` (mm, at the current font
// size); the lines after the first are to be indented by `indent`, under the text after "N: ".
struct WrappedStep {
  std::vector<std::string> lines;
  double indent = 0.0;
};

WrappedStep wrap_step(cairo_t* cr, const std::string& text, double width) {
  WrappedStep wrapped;
  const std::size_t colon = text.find(": ");
  wrapped.indent = colon == std::string::npos ? 0.0 : text_width(cr, text.substr(0, colon + 2));
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start + 1);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);  // with its leading space
    const double room = wrapped.lines.empty() ? width : width - wrapped.indent;
    if (!line.empty() && text_width(cr, line + word) > room) {
      wrapped.lines.push_back(line);
      line = word[0] == ' ' ? word.substr(1) : word;
    } else {
      line += word;
    }
    start = end;
  }
  if (!line.empty()) wrapped.lines.push_back(line);
  return wrapped;
}

// Whether steps of these wrapped lines fill at most `columns` columns of `rows` lines, a step
// never split between columns.
bool steps_fit(const std::vector<WrappedStep>& steps, int rows, int columns) {
  int column = 0, used = 0;
  for (const WrappedStep& step : steps) {
    const int lines = static_cast<int>(step.lines.size());
    if (used > 0 && used + lines > rows) {
      ++column;
      used = 0;
    }
    used += lines;
  }
  return column < columns;
}

// The build steps in columns from `top` down, on as many pages as they need: as few columns
// as hold them all on this page (wider columns wrap less), else the most the page takes.
void draw_build_steps(cairo_t* cr, const std::vector<std::string>& steps, const PageSize& page,
                      double top, const std::function<bool()>& next_page) {
  const double width = page.width_mm - 2 * kMargin;
  const int most_columns = width >= 150 ? 3 : width >= 90 ? 2 : 1;
  constexpr double kGap = 5.0;
  const double line = kLineSpacing * kStepTextMm;
  const double bottom = page.height_mm - kMargin;
  auto heading = [&](double y, const std::string& text) {
    cairo_set_font_size(cr, 3.5);
    cairo_move_to(cr, kMargin, y + 3.5);
    cairo_show_text(cr, text.c_str());
    cairo_set_font_size(cr, kStepTextMm);
    return y + 3.5 + 1.5 * line;
  };
  if (top + 6 * line > bottom) {
    if (!next_page()) return;
    top = kMargin;
  }
  double column_top =
      heading(top, "Build order (seams after \"then\" or \"close\" close a loop: glue them last)");
  const int rows = static_cast<int>(std::floor((bottom - column_top) / line)) + 1;
  int columns = 1;
  double column_width = width;
  std::vector<WrappedStep> wrapped;
  for (; columns <= most_columns; ++columns) {
    column_width = (width - kGap * (columns - 1)) / columns;
    wrapped.clear();
    for (const std::string& step : steps) wrapped.push_back(wrap_step(cr, step, column_width));
    if (steps_fit(wrapped, rows, columns) || columns == most_columns) break;
  }
  double y = column_top;
  int column = 0;
  for (std::size_t i = 0; i < wrapped.size(); ++i) {
    const std::vector<std::string>& lines = wrapped[i].lines;
    if (y + line * static_cast<double>(lines.size() - 1) > bottom) {
      if (++column == columns) {
        if (!next_page()) {
          cairo_move_to(cr, kMargin, bottom + line);
          const std::string more = "steps " + std::to_string(i + 1) + " to " +
                                   std::to_string(steps.size()) + ": next page of pattern.pdf";
          cairo_show_text(cr, more.c_str());
          return;
        }
        column = 0;
        column_top = heading(kMargin, "Build order, continued");
      }
      y = column_top;
    }
    const double x = kMargin + column * (column_width + kGap);
    for (std::size_t k = 0; k < lines.size(); ++k) {
      cairo_move_to(cr, x + (k == 0 ? 0.0 : wrapped[i].indent), y);
      cairo_show_text(cr, lines[k].c_str());
      y += line;
    }
  }
}

}  // namespace

void draw_guide(cairo_t* cr, const Guide& guide, const PageSize& page, const std::string& title,
                const std::string& font, const std::function<bool()>& next_page) {
  cairo_save(cr);
  cairo_select_font_face(cr, font.c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 5.0);
  cairo_move_to(cr, kMargin, kMargin + 5);
  const std::string heading = (title.empty() ? std::string("model") : title) + ": assembly guide";
  cairo_show_text(cr, heading.c_str());
  // The views over the top 62%, then the table of pages and the build steps.
  const double views_height = (page.height_mm - 2 * kMargin - 10) * 0.62;
  draw_views(cr, guide.pieces, page, kMargin + 10, views_height);
  cairo_set_source_rgb(cr, 0, 0, 0);
  const double bottom = page.height_mm - kMargin;
  const double after_table = draw_page_table(cr, guide.pieces, kMargin + 10 + views_height + 6,
                                             page.width_mm - 2 * kMargin, bottom);
  if (!guide.steps.empty()) draw_build_steps(cr, guide.steps, page, after_table, next_page);
  cairo_restore(cr);
}

std::string guide_png(const Guide& guide, const PageSize& page, const std::string& title,
                      double dpi) {
  const double pixels_per_mm = dpi / 25.4;
  const int w = static_cast<int>(std::ceil(page.width_mm * pixels_per_mm));
  const int h = static_cast<int>(std::ceil(page.height_mm * pixels_per_mm));
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_scale(cr, pixels_per_mm, pixels_per_mm);
  draw_guide(cr, guide, page, title, "sans-serif", [] { return false; });
  cairo_destroy(cr);
  std::string bytes = png_bytes(surface);
  cairo_surface_destroy(surface);
  if (bytes.empty()) throw IOException("guide.png: cairo could not encode the PNG");
  return bytes;
}

}  // namespace papercraft
