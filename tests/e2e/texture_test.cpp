// End to end: UVs and a PNG texture travel from an OBJ to the strips and into the PDF and
// SVG pages, on the strips and on their glue tabs.

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/generate.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

std::filesystem::path svg_name(const std::filesystem::path& dir, int page) {
  char name[32];
  std::snprintf(name, sizeof name, "pattern-%02d.svg", page);
  return dir / name;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string layer(const std::string& svg, const std::string& id) {
  const std::size_t begin = svg.find("id=\"" + id + "\"");
  if (begin == std::string::npos) return "";
  return svg.substr(begin, svg.find("</g>", begin) - begin);
}

// The subpaths ("M x,y L x,y ... Z") of every path in `svg`.
std::vector<std::vector<Vec2>> subpaths(const std::string& svg) {
  std::vector<std::vector<Vec2>> result;
  for (std::size_t at = svg.find(" d=\""); at != std::string::npos;
       at = svg.find(" d=\"", at + 1)) {
    std::istringstream in(svg.substr(at + 4, svg.find('"', at + 4) - at - 4));
    std::string token;
    while (in >> token) {
      if (token == "Z") continue;
      if (token[0] == 'M') result.emplace_back();
      double x = 0, y = 0;
      if (std::sscanf(token.c_str() + 1, "%lf,%lf", &x, &y) == 2) result.back().emplace_back(x, y);
    }
  }
  return result;
}

bool inside(const Vec2& p, const std::vector<Vec2>& polygon) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;  // rgb
};

// A binary PPM (P6, maxval 255) as pdftoppm writes it.
Image read_ppm(const std::string& path) {
  Image image;
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxval = 0;
  in >> magic >> image.width >> image.height >> maxval;
  in.get();
  if (magic != "P6" || maxval != 255) return {};
  image.pixels.resize(static_cast<std::size_t>(3 * image.width * image.height));
  in.read(reinterpret_cast<char*>(image.pixels.data()),
          static_cast<std::streamsize>(image.pixels.size()));
  if (!in) return {};
  return image;
}

TEST(Texture, UvsReachStripsAndTheTextureIsDrawnInThePdf) {
  const auto dir = testing::fresh_temp_dir("texture");
  // A checkerboard PNG.
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 64, 64);
  cairo_t* cr = cairo_create(image);
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      cairo_set_source_rgb(cr, (i + j) % 2 ? 0.9 : 0.1, 0.3, (i + j) % 2 ? 0.1 : 0.8);
      cairo_rectangle(cr, 8 * i, 8 * j, 8, 8);
      cairo_fill(cr);
    }
  }
  cairo_destroy(cr);
  ASSERT_EQ(cairo_surface_write_to_png(image, (dir / "checker.png").c_str()), CAIRO_STATUS_SUCCESS);
  cairo_surface_destroy(image);
  std::ofstream(dir / "tube.mtl") << "newmtl skin\nmap_Kd checker.png\n";
  // An open cylinder with seam-free uvs: u from cos(angle), v from height.
  const TriangleMesh tube = open_cylinder();
  std::ofstream obj(dir / "tube.obj");
  obj.precision(17);
  obj << "mtllib tube.mtl\nusemtl skin\n";
  for (const Vec3& p : tube.vertices) obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Vec3& p : tube.vertices)
    obj << "vt " << 0.5 * (p.x() + 1.0) << ' ' << 0.5 * p.z() << '\n';
  for (const Triangle& t : tube.triangles) {
    obj << "f";
    for (int v : t) obj << ' ' << v + 1 << '/' << v + 1;
    obj << '\n';
  }
  obj.close();

  const Registry& registry = builtin_registry();
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = parse_tolerance("1%");
  settings->output_dir = dir / "out";
  Pipeline pipeline(parse_pipeline_config(default_config_text(), "default.yaml", registry),
                    registry);
  const auto results = pipeline.run({dir / "tube.obj"}, settings);
  ASSERT_TRUE(results.at(0).ok) << results.at(0).error;
  const auto flat = nlohmann::json::parse(testing::read_text(dir / "out/tube/strips.json"));
  ASSERT_FALSE(flat.at("strips").empty());
  for (const auto& strip : flat.at("strips")) {
    ASSERT_TRUE(strip.contains("uv"));
    ASSERT_EQ(strip.at("uv").size(), strip.at("vertices3d").size());
    for (std::size_t i = 0; i < strip.at("uv").size(); ++i) {
      const double x = strip.at("vertices3d")[i][0], z = strip.at("vertices3d")[i][2];
      EXPECT_NEAR(strip.at("uv")[i][0].get<double>(), 0.5 * (x + 1.0), 1e-6);
      EXPECT_NEAR(strip.at("uv")[i][1].get<double>(), 0.5 * z, 1e-6);
    }
  }
  const std::string pdf = testing::read_text(dir / "out/tube/pattern.pdf");
  EXPECT_NE(pdf.find("/Subtype /Image"), std::string::npos) << "the texture is drawn";

  // The SVG embeds the texture once and paints it per triangle and per tab edge: more
  // clipped patches than the strips have triangles.
  std::size_t triangles = 0;
  for (const auto& strip : flat.at("strips")) triangles += strip.at("triangles").size();
  std::size_t patches = 0;
  std::vector<std::vector<Vec2>> flaps;  // of page 1
  for (int page = 1; std::filesystem::exists(svg_name(dir / "out/tube", page)); ++page) {
    const std::string svg = testing::read_text(svg_name(dir / "out/tube", page));
    EXPECT_EQ(count(svg, "<image id=\"texture\""), 1) << page;
    EXPECT_NE(svg.find("xlink:href=\"data:image/png;base64,iVBORw0KGgo"), std::string::npos);
    patches += count(svg, "<clipPath id=\"texture-clip-");
    EXPECT_EQ(count(svg, "<clipPath id=\"texture-clip-"),
              count(svg, "<use xlink:href=\"#texture\" transform=\"matrix("));
    if (page == 1) flaps = subpaths(layer(svg, "tabs"));
  }
  EXPECT_GT(patches, triangles) << "tabs carry the texture too";

  // Rendered, the middle of a tab shows the checkerboard (green 0.3), not the grey tab
  // fill (0.9) or white paper.
  if (std::system("command -v pdftoppm > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "pdftoppm not installed";
  ASSERT_FALSE(flaps.empty());
  constexpr double kDpi = 100;
  const auto ppm = dir / "page";
  ASSERT_EQ(std::system(("pdftoppm -r 100 -f 2 -l 2 -singlefile " +
                         (dir / "out/tube/pattern.pdf").string() + " " + ppm.string())
                            .c_str()),
            0);
  const Image page = read_ppm(ppm.string() + ".ppm");
  ASSERT_GT(page.width, 0);
  int sampled = 0, textured = 0;
  for (const auto& flap : flaps) {
    Vec2 centre = Vec2::Zero();
    for (const Vec2& p : flap) centre += p / static_cast<double>(flap.size());
    if (!inside(centre, flap)) continue;
    const int x = static_cast<int>(centre.x() / 25.4 * kDpi);
    const int y = static_cast<int>(centre.y() / 25.4 * kDpi);
    if (x < 0 || y < 0 || x >= page.width || y >= page.height) continue;
    const int green = page.pixels[3 * (y * page.width + x) + 1];
    ++sampled;
    if (std::abs(green - 77) < 30) ++textured;
  }
  ASSERT_GT(sampled, 0);
  EXPECT_GE(textured, (4 * sampled + 4) / 5) << textured << " of " << sampled;
}

}  // namespace
}  // namespace papercraft
