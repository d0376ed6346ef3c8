#include "nodes/export/pdf.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include "core/errors.h"

namespace papercraft {
namespace {

constexpr double kPointsPerMm = 72.0 / 25.4;

// "#rrggbb" -> cairo's 0..1 channels.
void set_colour(cairo_t* cr, const std::string& colour) {
  unsigned value = 0;
  if (colour.size() == 7 && colour[0] == '#') value = std::stoul(colour.substr(1), nullptr, 16);
  cairo_set_source_rgb(cr, ((value >> 16) & 0xff) / 255.0, ((value >> 8) & 0xff) / 255.0,
                       (value & 0xff) / 255.0);
}

void draw_path(cairo_t* cr, const DrawPath& path) {
  cairo_new_path(cr);
  bool any = false;
  for (const auto& line : path.polylines) {
    if (line.empty()) continue;
    any = true;
    cairo_move_to(cr, line[0].x(), line[0].y());
    for (std::size_t i = 1; i < line.size(); ++i) cairo_line_to(cr, line[i].x(), line[i].y());
    if (path.closed) cairo_close_path(cr);
  }
  if (!any) return;
  if (!path.fill.empty()) {
    set_colour(cr, path.fill);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    cairo_fill_preserve(cr);
  }
  if (path.stroked) {
    set_colour(cr, path.pen.colour);
    cairo_set_line_width(cr, path.pen.width_mm);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_dash(cr, path.pen.dash_mm.data(), static_cast<int>(path.pen.dash_mm.size()), 0.0);
    cairo_stroke(cr);
  }
  cairo_new_path(cr);
}

void draw_text(cairo_t* cr, const DrawText& text, const std::string& font) {
  const Label& l = text.label;
  if (l.text.empty()) return;
  cairo_save(cr);
  cairo_select_font_face(cr, font.c_str(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, l.size_mm);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, l.text.c_str(), &extents);
  cairo_font_extents_t font_extents;
  cairo_font_extents(cr, &font_extents);
  cairo_translate(cr, l.position.x(), l.position.y());
  cairo_rotate(cr, l.angle_degrees * M_PI / 180.0);
  // Centred horizontally on the advance and vertically between ascent and descent, as SVG's
  // text-anchor="middle" dominant-baseline="central" does.
  cairo_move_to(cr, -0.5 * extents.x_advance, 0.5 * (font_extents.ascent - font_extents.descent));
  set_colour(cr, text.colour);
  cairo_show_text(cr, l.text.c_str());
  cairo_new_path(cr);
  cairo_restore(cr);
}

// Paints the pieces' baked print images at their place on the page.
void draw_images(cairo_t* cr, const std::vector<BakedImage>& images) {
  for (const BakedImage& image : images) {
    if (image.width <= 0 || image.height <= 0) continue;
    const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, image.width);
    std::vector<unsigned char> data(std::size_t(stride) * image.height);
    for (int y = 0; y < image.height; ++y)
      std::memcpy(&data[std::size_t(y) * stride], &image.argb[std::size_t(y) * image.width],
                  std::size_t(image.width) * 4);
    cairo_surface_t* surface = cairo_image_surface_create_for_data(
        data.data(), CAIRO_FORMAT_ARGB32, image.width, image.height, stride);
    cairo_save(cr);
    cairo_translate(cr, image.origin.x(), image.origin.y());
    cairo_scale(cr, image.pixel_mm, image.pixel_mm);
    cairo_set_source_surface(cr, surface, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(surface);
  }
}

// cairo's write function: appends to the std::ostream `closure`.
cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto& out = *static_cast<std::ostream*>(closure);
  out.write(reinterpret_cast<const char*>(data), length);
  return out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
};

}  // namespace

void write_pattern_pdf(const PatternLayout& layout, std::ostream& out, const StyleOptions& style,
                       const Guide* guide, const std::string& what) {
  const double width = layout.page.width_mm * kPointsPerMm;
  const double height = layout.page.height_mm * kPointsPerMm;
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(
      cairo_pdf_surface_create_for_stream(write_to_stream, &out, width, height));
  auto fail = [&](cairo_status_t status) {
    throw IOException("cannot write PDF '" + what + "': " + cairo_status_to_string(status));
  };
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    fail(cairo_surface_status(surface.get()));
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE,
                                 style.title.empty() ? "papercraft pattern" : style.title.c_str());
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "papercraft");
  {
    std::unique_ptr<cairo_t, ContextDeleter> cr(cairo_create(surface.get()));
    cairo_scale(cr.get(), kPointsPerMm, kPointsPerMm);
    if (guide && !layout.pages.empty()) {
      draw_guide(cr.get(), *guide, layout.page, style.title, style.font_family, [&] {
        cairo_show_page(cr.get());
        return true;
      });
      cairo_show_page(cr.get());
    }
    for (int page = 0; page < static_cast<int>(layout.pages.size()); ++page) {
      if (style.images && static_cast<std::size_t>(page) < style.images->size())
        draw_images(cr.get(), (*style.images)[page]);
      for (const DrawLayer& layer : pattern_page_drawing(layout, page, style)) {
        for (const DrawPath& p : layer.paths) draw_path(cr.get(), p);
        for (const DrawText& t : layer.texts) draw_text(cr.get(), t, style.font_family);
      }
      cairo_show_page(cr.get());
    }
    if (layout.pages.empty()) cairo_show_page(cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) fail(cairo_status(cr.get()));
  }
  cairo_surface_finish(surface.get());
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    fail(cairo_surface_status(surface.get()));
}

void write_pattern_pdf(const PatternLayout& layout, const std::filesystem::path& path,
                       const StyleOptions& style, const Guide* guide) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw IOException("cannot write PDF '" + path.string() + "': cannot open the file");
  write_pattern_pdf(layout, out, style, guide, path.string());
  out.close();
  if (!out) throw IOException("cannot write PDF '" + path.string() + "': write error");
}

}  // namespace papercraft
