#include "nodes/export/assembly_html.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/build_order.h"
#include "nodes/export/assembly_template.h"
#include "nodes/layout/pages.h"
#include "support/layout_strips.h"

namespace papercraft {
namespace {

using testing::prism_strips;
using testing::square_footprint;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string from_base64(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string raw;
  unsigned bits = 0, count = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<unsigned>(digits.find(c));
    if ((count += 6) >= 8) raw += static_cast<char>((bits >> (count -= 8)) & 0xff);
  }
  return raw;
}

std::string gunzip(const std::string& bytes) {
  z_stream stream{};
  EXPECT_EQ(inflateInit2(&stream, 15 + 16), Z_OK);
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  std::string out;
  char buffer[1 << 16];
  int status = Z_OK;
  while (status == Z_OK) {
    stream.next_out = reinterpret_cast<Bytef*>(buffer);
    stream.avail_out = sizeof buffer;
    status = inflate(&stream, Z_NO_FLUSH);
    out.append(buffer, sizeof buffer - stream.avail_out);
  }
  EXPECT_EQ(status, Z_STREAM_END);
  inflateEnd(&stream);
  return out;
}

// Little-endian unsigned integers of `bytes` bytes each, from base64 (the page's packing).
std::vector<std::uint32_t> unpacked(const std::string& text, int bytes) {
  const std::string raw = from_base64(text);
  EXPECT_EQ(raw.size() % bytes, 0u);
  std::vector<std::uint32_t> values(raw.size() / bytes, 0);
  for (std::size_t i = 0; i < raw.size(); ++i)
    values[i / bytes] |= static_cast<std::uint32_t>(static_cast<unsigned char>(raw[i]))
                         << (8 * (i % bytes));
  return values;
}

const std::string kDataOpen = "<script id=\"papercraft-data\" type=\"application/gzip\">";

// The text the page carries its data in.
std::string data_text(const std::string& html) {
  const std::size_t start = html.find(kDataOpen);
  EXPECT_NE(start, std::string::npos);
  const std::size_t end = html.find("</script>", start);
  return html.substr(start + kDataOpen.size(), end - start - kDataOpen.size());
}

// The model's data as the page holds it.
nlohmann::json page_data(const std::string& html) {
  return nlohmann::json::parse(gunzip(from_base64(data_text(html))));
}

struct Prism {
  std::vector<FlatStrip> strips = prism_strips(square_footprint(40), 60, 0);
  PatternLayout layout;
  BuildOrder order;
  Prism() {
    LayoutOptions options;
    options.scale = 1;
    layout = layout_pages(strips, options);
    order = build_order(layout);
  }
};

TEST(AssemblyHtml, TemplateHoldsEachPlaceholderOnce) {
  const std::string page(assembly_page_template());
  EXPECT_EQ(count(page, "@PAPERCRAFT_TITLE@"), 1u);
  EXPECT_EQ(count(page, "@PAPERCRAFT_DATA@"), 1u);
  EXPECT_EQ(count(page, "@PAPERCRAFT_SCRIPT@"), 0u);
  EXPECT_EQ(count(page, "<script"), count(page, "</script>"));
  EXPECT_NE(page.find("Three.js Authors"), std::string::npos)
      << "the bundle keeps three.js' licence";
}

TEST(AssemblyHtml, PiecesStepsAndPagesOfAPrism) {
  const Prism prism;
  StyleOptions style;
  style.title = "prism";
  const AssemblyHtml page = assembly_html(prism.layout, prism.strips, prism.order, style);
  EXPECT_TRUE(page.notes.empty());
  const nlohmann::json data = page_data(page.text);
  EXPECT_EQ(data.at("name"), "prism");
  ASSERT_EQ(data.at("pieces").size(), 3u);
  EXPECT_EQ(data.at("steps").size(), 3u);
  EXPECT_EQ(data.at("pages_svg").size(), prism.layout.pages.size());
  EXPECT_EQ(data.at("pages_svg")[0].get<std::string>().rfind("<?xml", 0), 0u);
  // The band (strip 0, the largest and in the middle) comes first and closes itself along A.
  const BuildStep& first = prism.order.steps.front();
  const nlohmann::json& first_step = data.at("steps")[0];
  EXPECT_EQ(first_step.at("piece"), first.piece);
  EXPECT_EQ(first_step.at("text"), build_step_text(first));
  EXPECT_EQ(first_step.at("seams"), nlohmann::json::array({"A"}));
  for (const nlohmann::json& piece : data.at("pieces")) {
    const std::vector<std::uint32_t> points = unpacked(piece.at("points"), 2);
    ASSERT_EQ(points.size() % 3, 0u);
    const std::size_t vertices = points.size() / 3;
    EXPECT_EQ(piece.at("index_bytes"), 2);
    for (std::uint32_t i : unpacked(piece.at("triangles"), 2)) EXPECT_LT(i, vertices);
    for (const auto& seam : piece.at("seams")) {
      EXPECT_EQ(seam.at("edges").size() % 2, 0u);
      EXPECT_FALSE(seam.at("edges").empty()) << seam.at("label");
      for (const auto& i : seam.at("edges")) EXPECT_LT(i.get<std::size_t>(), vertices);
    }
    EXPECT_EQ(piece.at("colour").get<std::string>().size(), 7u);
    EXPECT_GE(piece.at("step").get<int>(), 1);
  }
  // The band's points on the grid, in mm at print scale (1 mm per unit): 60 mm tall, to a
  // step of the grid (60 mm over 65,535 steps, the model's largest side).
  const double step = data.at("grid").at("step").get<double>();
  EXPECT_NEAR(step, 60.0 / 65535, 1e-12);
  const nlohmann::json& band =
      *std::find_if(data.at("pieces").begin(), data.at("pieces").end(),
                    [&](const nlohmann::json& p) { return p.at("name") == first.piece; });
  const std::vector<std::uint32_t> points = unpacked(band.at("points"), 2);
  std::uint32_t lowest = 65535, highest = 0;
  for (std::size_t i = 2; i < points.size(); i += 3) {
    lowest = std::min(lowest, points[i]);
    highest = std::max(highest, points[i]);
  }
  EXPECT_NEAR((highest - lowest) * step, 60.0, step);
}

TEST(AssemblyHtml, NamesCannotEndTheScriptOrTheTitle) {
  const Prism prism;
  StyleOptions style;
  style.title = "a \"b\" 'c' </script><script>alert(1)</script> <!-- & caf\xC3\xA9 \xE9";
  const AssemblyHtml page = assembly_html(prism.layout, prism.strips, prism.order, style);
  const std::string page_template(assembly_page_template());
  EXPECT_EQ(count(page.text, "</script"), count(page_template, "</script"));
  EXPECT_EQ(count(page.text, "<!--"), count(page_template, "<!--"));
  EXPECT_EQ(count(page.text, "alert(1)</"), 0u);
  EXPECT_NE(
      page.text.find("<title>a &quot;b&quot; &apos;c&apos; &lt;/script&gt;&lt;script&gt;alert(1)"
                     "&lt;/script&gt; &lt;!-- &amp; caf\xC3\xA9 \\xE9: assembly</title>"),
      std::string::npos);
  // The data is base64; the name comes back whole, the byte that is not UTF-8 as \xE9.
  EXPECT_EQ(data_text(page.text).find_first_not_of(
                "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/="),
            std::string::npos);
  EXPECT_EQ(page_data(page.text).at("name"),
            "a \"b\" 'c' </script><script>alert(1)</script> <!-- & caf\xC3\xA9 \\xE9");
}

TEST(AssemblyHtml, StaysUnderItsSizeByLeavingOutImagesThenPages) {
  const Prism prism;
  StyleOptions style;
  style.title = "prism";
  const std::size_t full =
      assembly_html(prism.layout, prism.strips, prism.order, style).text.size();
  // A noisy print image on every page, as a textured model has.
  std::vector<std::vector<BakedImage>> images(prism.layout.pages.size());
  for (auto& page : images) {
    BakedImage image;
    image.origin = Vec2(20, 20);
    image.pixel_mm = 0.25;
    image.width = image.height = 200;
    std::uint32_t state = 12345;
    for (int i = 0; i < image.width * image.height; ++i) {
      state = state * 1664525u + 1013904223u;
      image.argb.push_back(0xff000000u | (state >> 8));
    }
    page.push_back(image);
  }
  style.images = &images;
  const std::size_t with_images =
      assembly_html(prism.layout, prism.strips, prism.order, style).text.size();
  ASSERT_GT(with_images, full + 100'000);

  AssemblyHtmlOptions options;
  options.max_bytes = full + 1000;  // room for the pages, not for their images
  AssemblyHtml page = assembly_html(prism.layout, prism.strips, prism.order, style, options);
  EXPECT_LE(page.text.size(), options.max_bytes);
  ASSERT_EQ(page.notes.size(), 1u);
  EXPECT_NE(page.notes[0].find("print images are left out"), std::string::npos);
  EXPECT_EQ(page_data(page.text).at("pages_svg").size(), prism.layout.pages.size());
  EXPECT_EQ(page_data(page.text).at("notes"), nlohmann::json(page.notes));

  options.max_bytes = full - 1000;  // not even for the pages
  page = assembly_html(prism.layout, prism.strips, prism.order, style, options);
  EXPECT_LE(page.text.size(), options.max_bytes);
  ASSERT_EQ(page.notes.size(), 1u);
  EXPECT_NE(page.notes[0].find("pattern pages are left out"), std::string::npos);
  EXPECT_TRUE(page_data(page.text).at("pages_svg").empty());
  EXPECT_EQ(page_data(page.text).at("pieces").size(), 3u);

  options.max_bytes = 1000;  // not even for the 3D pieces: written all the same, and said so
  page = assembly_html(prism.layout, prism.strips, prism.order, style, options);
  ASSERT_EQ(page.notes.size(), 2u);
  EXPECT_NE(page.notes[1].find("over 0.0 MB"), std::string::npos) << page.notes[1];
  EXPECT_EQ(page_data(page.text).at("pieces").size(), 3u);
}

TEST(AssemblyHtml, EmptyLayoutGivesAPageWithoutPieces) {
  const AssemblyHtml page = assembly_html(PatternLayout{}, {}, BuildOrder{}, StyleOptions{});
  const nlohmann::json data = page_data(page.text);
  EXPECT_TRUE(data.at("pieces").empty());
  EXPECT_TRUE(data.at("steps").empty());
  EXPECT_EQ(data.at("name"), "model");
}

}  // namespace
}  // namespace papercraft
