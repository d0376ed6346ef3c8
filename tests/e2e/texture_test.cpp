// End to end: UVs and a PNG texture travel from an OBJ to the strips and into the PDF.

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/generate.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

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
}

}  // namespace
}  // namespace papercraft
