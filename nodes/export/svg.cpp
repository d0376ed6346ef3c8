#include "nodes/export/svg.h"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "nodes/export/base64.h"

namespace papercraft {
namespace {

// Millimetres to `decimals` decimals (3: a micrometre), without trailing zeros.
std::string number(double value, int decimals = 3) {
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) return "0";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string text = buffer;
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}

std::string path_data(const DrawPath& path, int decimals) {
  std::string d;
  for (const auto& line : path.polylines) {
    if (line.empty()) continue;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (!d.empty()) d += ' ';
      d += i == 0 ? 'M' : 'L';
      d += number(line[i].x(), decimals);
      d += ',';
      d += number(line[i].y(), decimals);
    }
    if (path.closed) d += " Z";
  }
  return d;
}

void write_path(std::ostringstream& out, const DrawPath& path, int decimals) {
  const std::string d = path_data(path, decimals);
  if (d.empty()) return;
  out << "    <path d=\"" << d << "\" fill=\"" << (path.fill.empty() ? "none" : path.fill) << "\"";
  if (path.stroked) {
    out << " stroke=\"" << path.pen.colour << "\" stroke-width=\"" << number(path.pen.width_mm)
        << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"";
    if (!path.pen.dash_mm.empty()) {
      out << " stroke-dasharray=\"";
      for (std::size_t i = 0; i < path.pen.dash_mm.size(); ++i)
        out << (i ? "," : "") << number(path.pen.dash_mm[i]);
      out << "\"";
    }
  } else {
    out << " stroke=\"none\"";
  }
  out << "/>\n";
}

void write_text(std::ostringstream& out, const DrawText& text, const std::string& font,
                int decimals) {
  const Label& l = text.label;
  if (l.text.empty()) return;
  const std::string x = number(l.position.x(), decimals), y = number(l.position.y(), decimals);
  out << "    <text x=\"" << x << "\" y=\"" << y << "\" font-family=\"" << xml_escaped(font)
      << "\" font-size=\"" << number(l.size_mm) << "\" fill=\"" << text.colour
      << "\" text-anchor=\"middle\" dominant-baseline=\"central\"";
  if (std::abs(l.angle_degrees) > 1e-9)
    out << " transform=\"rotate(" << number(l.angle_degrees) << " " << x << " " << y << ")\"";
  out << ">" << xml_escaped(l.text) << "</text>\n";
}

// A PNG file's bytes and pixel size (from its IHDR chunk); empty when unreadable or not a PNG.
struct Png {
  std::string bytes;
  int width = 0;
  int height = 0;
};

// The pieces' baked print images, as embedded PNGs at their place on the page.
void write_images(std::ostringstream& out, const std::vector<BakedImage>& images) {
  for (const BakedImage& image : images) {
    if (image.width <= 0 || image.height <= 0) continue;
    out << "    <image x=\"" << number(image.origin.x()) << "\" y=\"" << number(image.origin.y())
        << "\" width=\"" << number(image.width * image.pixel_mm) << "\" height=\""
        << number(image.height * image.pixel_mm)
        << "\" preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64,"
        << base64(png_bytes(image)) << "\"/>\n";
  }
}

}  // namespace

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // Control characters are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n') out += c;
    }
  }
  return out;
}

std::string pattern_page_svg(const PatternLayout& layout, int page_index,
                             const StyleOptions& style) {
  const std::vector<DrawLayer> layers = pattern_page_drawing(layout, page_index, style);
  const std::string width = number(layout.page.width_mm), height = number(layout.page.height_mm);
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\"\n"
      << "     xmlns:xlink=\"http://www.w3.org/1999/xlink\"\n"
      << "     xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"\n"
      << "     version=\"1.1\" width=\"" << width << "mm\" height=\"" << height
      << "mm\" viewBox=\"0 0 " << width << " " << height << "\">\n"
      << "  <title>" << xml_escaped(style.title.empty() ? "papercraft pattern" : style.title)
      << ", page " << page_index + 1 << " of " << layout.pages.size() << "</title>\n";
  for (const DrawLayer& layer : layers) {
    out << "  <g inkscape:groupmode=\"layer\" id=\"" << layer.id << "\" inkscape:label=\""
        << layer.id << "\">\n";
    if (&layer == &layers.front() && style.images &&
        static_cast<std::size_t>(page_index) < style.images->size())
      write_images(out, (*style.images)[static_cast<std::size_t>(page_index)]);
    for (const DrawPath& path : layer.paths) write_path(out, path, style.svg_decimals);
    for (const DrawText& text : layer.texts)
      write_text(out, text, style.font_family, style.svg_decimals);
    out << "  </g>\n";
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace papercraft
