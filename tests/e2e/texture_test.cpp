// End to end: what is printed on the pieces is baked from the input surface (textures through
// per-corner UVs, several materials, colours), checked on the rendered PDF: the pixel at a
// point well inside a piece's triangle shows the colour of the input under the 3D point it
// comes from.

#include <cairo.h>
#include <gtest/gtest.h>
// clang-format off
#include <cstdio>
#include <jpeglib.h>
// clang-format on

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/generate.h"
#include "support/brute_force_hausdorff.h"
#include "support/pipeline_run.h"
#include "support/scene_writers.h"

namespace papercraft {
namespace {

struct Rgb {
  int r, g, b;
};

void write_png(const std::filesystem::path& path, int width, int height,
               const std::function<Rgb(int, int)>& colour) {
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_surface_flush(image);
  unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Rgb c = colour(x, y);
      const std::uint32_t pixel = 0xff000000u | (c.r << 16) | (c.g << 8) | c.b;
      std::memcpy(data + y * stride + 4 * x, &pixel, 4);
    }
  cairo_surface_mark_dirty(image);
  ASSERT_EQ(cairo_surface_write_to_png(image, path.c_str()), CAIRO_STATUS_SUCCESS);
  cairo_surface_destroy(image);
}

// The same pixels as a JPEG (quality 95), through libjpeg.
void write_jpeg(const std::filesystem::path& path, int width, int height,
                const std::function<Rgb(int, int)>& colour) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  jpeg_compress_struct info;
  jpeg_error_mgr error;
  info.err = jpeg_std_error(&error);
  jpeg_create_compress(&info);
  jpeg_stdio_dest(&info, file);
  info.image_width = width;
  info.image_height = height;
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, 95, TRUE);
  jpeg_start_compress(&info, TRUE);
  std::vector<unsigned char> row(3 * width);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Rgb c = colour(x, y);
      row[3 * x] = c.r, row[3 * x + 1] = c.g, row[3 * x + 2] = c.b;
    }
    JSAMPROW pointer = row.data();
    jpeg_write_scanlines(&info, &pointer, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::fclose(file);
}

struct Ppm {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
};

Ppm read_ppm(const std::string& path) {
  Ppm image;
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxval = 0;
  in >> magic >> image.width >> image.height >> maxval;
  in.get();
  if (magic != "P6" || maxval != 255) return {};
  image.pixels.resize(static_cast<std::size_t>(3 * image.width * image.height));
  in.read(reinterpret_cast<char*>(image.pixels.data()),
          static_cast<std::streamsize>(image.pixels.size()));
  return image;
}

struct Checked {
  int sampled = 0;
  int matching = 0;
  int split = 0, small = 0, undecided = 0, off_page = 0;  // skipped, and why
  std::string first_miss;
};

std::ostream& operator<<(std::ostream& out, const Checked& c) {
  return out << c.matching << " of " << c.sampled << " (skipped: split " << c.split << ", small "
             << c.small << ", undecided " << c.undecided << ", off page " << c.off_page
             << "; first miss " << c.first_miss << ")";
}

// Renders every pattern page of the run in `dir` and compares, at points well inside each
// piece's triangles, the printed colour with `expected(3D point)` (nullopt: the point is too
// near a colour boundary to judge).
Checked check_printed_colours(const std::filesystem::path& dir,
                              const std::function<std::optional<Rgb>(const Vec3&)>& expected) {
  constexpr double kDpi = 100;
  Checked checked;
  const auto strips = nlohmann::json::parse(testing::read_text(dir / "strips.json")).at("strips");
  const auto pieces = nlohmann::json::parse(testing::read_text(dir / "pieces.json")).at("pieces");
  std::map<int, const nlohmann::json*> by_id;
  for (const auto& strip : strips) by_id[strip.at("id").get<int>()] = &strip;
  std::map<int, Ppm> pages;
  for (const auto& piece : pieces) {
    const int page = piece.at("page").get<int>();
    if (!pages.count(page)) {
      const auto ppm = dir / ("render-" + std::to_string(page));
      const int pdf_page = page + 1;  // the assembly guide comes first
      const std::string command = "pdftoppm -r 100 -f " + std::to_string(pdf_page) + " -l " +
                                  std::to_string(pdf_page) + " -singlefile '" +
                                  (dir / "pattern.pdf").string() + "' '" + ppm.string() + "'";
      EXPECT_EQ(std::system(command.c_str()), 0) << command;
      pages[page] = read_ppm(ppm.string() + ".ppm");
    }
    const Ppm& image = pages[page];
    const auto& t = piece.at("transform");
    Eigen::Matrix2d linear;
    linear << t.at("linear")[0].get<double>(), t.at("linear")[1].get<double>(),
        t.at("linear")[2].get<double>(), t.at("linear")[3].get<double>();
    const Vec2 translation(t.at("translation")[0].get<double>(),
                           t.at("translation")[1].get<double>());
    const nlohmann::json& strip = *by_id.at(piece.at("strip").get<int>());
    // A split strip's triangles are on several pieces: judge only those whose centre maps
    // into the page (and is covered by this piece: a whole strip when not split).
    if (piece.at("piece_count").get<int>() > 1) {
      ++checked.split;
      continue;
    }
    auto sample = [&](const Vec2& centre, const Vec3& point) {
      const auto want = expected(point);
      if (!want) {
        ++checked.undecided;
        return;
      }
      const int x = static_cast<int>(centre.x() / 25.4 * kDpi);
      const int y = static_cast<int>(centre.y() / 25.4 * kDpi);
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) {
        ++checked.off_page;
        return;
      }
      // The median of a 5 x 5 window: a fold line or a letter printed over the image is thin.
      unsigned char got[3];
      for (int channel = 0; channel < 3; ++channel) {
        std::vector<unsigned char> values;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int px = std::clamp(x + dx, 0, image.width - 1);
            const int py = std::clamp(y + dy, 0, image.height - 1);
            values.push_back(image.pixels[3 * (std::size_t(py) * image.width + px) + channel]);
          }
        std::nth_element(values.begin(), values.begin() + 12, values.end());
        got[channel] = values[12];
      }
      ++checked.sampled;
      if (std::abs(got[0] - want->r) < 40 && std::abs(got[1] - want->g) < 40 &&
          std::abs(got[2] - want->b) < 40) {
        ++checked.matching;
      } else if (checked.first_miss.empty()) {
        checked.first_miss = "at (" + std::to_string(point.x()) + ", " + std::to_string(point.y()) +
                             ", " + std::to_string(point.z()) + ") got " + std::to_string(got[0]) +
                             "," + std::to_string(got[1]) + "," + std::to_string(got[2]) +
                             " want " + std::to_string(want->r) + "," + std::to_string(want->g) +
                             "," + std::to_string(want->b);
      }
    };
    for (const auto& tri : strip.at("triangles")) {
      Vec2 page_corner[3];
      Vec3 corner3[3];
      for (int k = 0; k < 3; ++k) {
        const int v = tri[k].get<int>();
        const auto& p2 = strip.at("vertices2d")[v];
        page_corner[k] = linear * Vec2(p2[0].get<double>(), p2[1].get<double>()) + translation;
        const auto& p3 = strip.at("vertices3d")[v];
        corner3[k] = Vec3(p3[0].get<double>(), p3[1].get<double>(), p3[2].get<double>());
      }
      // Points on a barycentric grid inside the triangle, each at least 3 pixels from its
      // edges (the 5 x 5 window below stays inside).
      const Vec2 e1 = page_corner[1] - page_corner[0], e2 = page_corner[2] - page_corner[0];
      const double twice_area = std::abs(e1.x() * e2.y() - e1.y() * e2.x());
      if (twice_area <= 0) continue;
      double heights[3];
      for (int k = 0; k < 3; ++k)
        heights[k] = twice_area / (page_corner[(k + 2) % 3] - page_corner[(k + 1) % 3]).norm();
      constexpr int kGrid = 6;
      for (int i = 1; i < kGrid; ++i)
        for (int j = 1; i + j < kGrid; ++j) {
          const double w[3] = {double(i) / kGrid, double(j) / kGrid, double(kGrid - i - j) / kGrid};
          bool inside = true;
          for (int k = 0; k < 3; ++k) inside = inside && w[k] * heights[k] >= 3 * 25.4 / kDpi;
          if (!inside) {
            ++checked.small;
            continue;
          }
          const Vec2 centre = w[0] * page_corner[0] + w[1] * page_corner[1] + w[2] * page_corner[2];
          const Vec3 point = w[0] * corner3[0] + w[1] * corner3[1] + w[2] * corner3[2];
          sample(centre, point);
        }
    }
  }
  return checked;
}

testing::PipelineOutput run_file(const std::filesystem::path& input, const std::string& tolerance) {
  const Registry& registry = builtin_registry();
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = parse_tolerance(tolerance);
  settings->output_dir = input.parent_path() / "out";
  settings->paper.height_mm = 90;  // small enough that no strip is split for the page
  Pipeline pipeline(parse_pipeline_config(default_config_text(), "default.yaml", registry),
                    registry);
  testing::PipelineOutput out;
  out.result = pipeline.run({input}, settings).at(0);
  out.dir = settings->output_dir / input.stem();
  if (out.result.ok)
    out.report = nlohmann::json::parse(testing::read_text(out.dir / "report.json"));
  return out;
}

constexpr Rgb kSideColours[6] = {{220, 40, 40},  {40, 180, 60},  {40, 70, 220},
                                 {230, 200, 40}, {200, 60, 200}, {40, 200, 210}};

// The colour of the atlas box (testing::atlas_box) at a point of its surface: its side's
// colour; undecided within 0.1 of an edge.
std::optional<Rgb> atlas_box_colour(const Vec3& p) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(p[k]) > std::abs(p[axis])) axis = k;
  for (int k = 0; k < 3; ++k)
    if (k != axis && std::abs(p[k]) > 0.9) return std::nullopt;
  return kSideColours[2 * axis + (p[axis] > 0 ? 1 : 0)];
}

// A cube whose six faces are separate UV islands of one atlas, each a solid colour: the
// cells of a 3 x 2 grid, so every cube edge is a UV seam.
TEST(Texture, CubeOfSixUvIslandsPrintsEachFaceInItsColour) {
  const auto dir = testing::fresh_temp_dir("atlas_cube");
  write_png(dir / "atlas.png", 96, 64,
            [](int x, int y) { return kSideColours[(y / 32) * 3 + x / 32]; });
  std::ofstream(dir / "cube.mtl") << "newmtl atlas\nmap_Kd atlas.png\n";
  testing::write_obj(dir / "cube.obj", testing::atlas_box(), "mtllib cube.mtl\nusemtl atlas\n");
  const auto out = run_file(dir / "cube.obj", "2%");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  // report.json says what was baked: one image per printed piece, and what it cost.
  const auto& texture = out.report.at("texture");
  EXPECT_GE(texture.at("baked_images").get<int>(), 1);
  EXPECT_GT(texture.at("baked_pixels").get<long>(), 0);
  EXPECT_GT(texture.at("bake_seconds").get<double>(), 0.0);
  EXPECT_GT(texture.at("bake_cpu_seconds").get<double>(), 0.0);
  if (std::system("command -v pdftoppm > /dev/null 2>&1") != 0) GTEST_SKIP() << "no pdftoppm";
  const Checked checked = check_printed_colours(out.dir, atlas_box_colour);
  EXPECT_GT(checked.sampled, 50) << checked;
  EXPECT_GE(checked.matching, 0.99 * checked.sampled) << checked;
  std::cout << "[ colours  ] " << checked << "\n";
}

// The atlas cube with a JPEG texture.
TEST(Texture, JpegTexturePrintsEachFaceInItsColour) {
  const auto dir = testing::fresh_temp_dir("atlas_jpeg");
  write_jpeg(dir / "atlas.jpg", 96, 64,
             [](int x, int y) { return kSideColours[(y / 32) * 3 + x / 32]; });
  std::ofstream(dir / "cube.mtl") << "newmtl atlas\nmap_Kd atlas.jpg\n";
  testing::write_obj(dir / "cube.obj", testing::atlas_box(), "mtllib cube.mtl\nusemtl atlas\n");
  const auto out = run_file(dir / "cube.obj", "2%");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  EXPECT_GE(out.report.at("texture").at("baked_images").get<int>(), 1);
  EXPECT_TRUE(out.report.at("notes").dump().find("not printed") == std::string::npos)
      << out.report.at("notes");
  if (std::system("command -v pdftoppm > /dev/null 2>&1") != 0) GTEST_SKIP() << "no pdftoppm";
  const Checked checked = check_printed_colours(out.dir, atlas_box_colour);
  EXPECT_GT(checked.sampled, 50) << checked;
  EXPECT_GE(checked.matching, 0.99 * checked.sampled) << checked;
}

// The same atlas cube as a GLB with the PNG inside it: the image the GLB holds is printed.
TEST(Texture, GlbWithItsEmbeddedTexturePrintsEachFaceInItsColour) {
  const auto dir = testing::fresh_temp_dir("atlas_glb");
  write_png(dir / "atlas.png", 96, 64,
            [](int x, int y) { return kSideColours[(y / 32) * 3 + x / 32]; });
  testing::GltfOptions options;
  {
    std::ifstream png(dir / "atlas.png", std::ios::binary);
    options.png.assign(std::istreambuf_iterator<char>(png), {});
  }
  std::filesystem::remove(dir / "atlas.png");  // only the copy inside the GLB is left
  ASSERT_TRUE(testing::write_gltf(dir / "cube.glb", testing::atlas_box(), options));
  const auto out = run_file(dir / "cube.glb", "2%");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  EXPECT_GE(out.report.at("texture").at("baked_images").get<int>(), 1);
  if (std::system("command -v pdftoppm > /dev/null 2>&1") != 0) GTEST_SKIP() << "no pdftoppm";
  const Checked checked = check_printed_colours(out.dir, atlas_box_colour);
  EXPECT_GT(checked.sampled, 50) << checked;
  EXPECT_GE(checked.matching, 0.99 * checked.sampled) << checked;
}

// A capped cylinder whose side is unwrapped around the axis (u wraps from 1 back to 0 on one
// column) and whose caps are UV discs of their own: bands of colour by angle on the side, a
// solid colour per cap.
TEST(Texture, CappedCylinderAcrossItsUvSeamAndCaps) {
  const auto dir = testing::fresh_temp_dir("capped");
  constexpr Rgb kBands[4] = {{220, 40, 40}, {240, 160, 30}, {230, 220, 40}, {210, 80, 160}};
  constexpr Rgb kTop{40, 180, 60}, kBottom{40, 70, 220};
  write_png(dir / "atlas.png", 128, 128, [&](int x, int y) {
    if (y < 64) return kBands[x / 32];
    return x < 64 ? kTop : kBottom;
  });
  std::ofstream(dir / "can.mtl") << "newmtl label\nmap_Kd atlas.png\n";
  const TriangleMesh can = generate_shape("capped_cylinder", {});
  std::ofstream obj(dir / "can.obj");
  obj.precision(17);
  obj << "mtllib can.mtl\nusemtl label\n";
  for (const Vec3& p : can.vertices) obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  int vt = 0;
  auto angle_u = [](const Vec3& p) {
    return (std::atan2(p.y(), p.x()) + std::numbers::pi) / (2 * std::numbers::pi);
  };
  for (const Triangle& t : can.triangles) {
    const Vec3 n =
        (can.vertices[t[1]] - can.vertices[t[0]]).cross(can.vertices[t[2]] - can.vertices[t[0]]);
    const bool cap = std::abs(n.normalized().z()) > 0.9;
    double us[3];
    for (int k = 0; k < 3; ++k) us[k] = angle_u(can.vertices[t[k]]);
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = can.vertices[t[k]];
      if (cap) {
        const double cu = n.z() > 0 ? 0.25 : 0.75;
        obj << "vt " << cu + 0.2 * p.x() << ' ' << 0.25 + 0.2 * p.y() << '\n';
      } else {
        // The column that wraps: its corners at u near 0 go to u + 1, so it spans the seam.
        double u = us[k];
        const double top = std::max({us[0], us[1], us[2]});
        if (top - u > 0.5) u += 1.0;
        obj << "vt " << u << ' ' << 0.5 + 0.45 * (p.z() + 1) / 2 << '\n';
      }
    }
    obj << "f " << t[0] + 1 << '/' << vt + 1 << ' ' << t[1] + 1 << '/' << vt + 2 << ' ' << t[2] + 1
        << '/' << vt + 3 << '\n';
    vt += 3;
  }
  obj.close();
  const auto out = run_file(dir / "can.obj", "2%");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  if (std::system("command -v pdftoppm > /dev/null 2>&1") != 0) GTEST_SKIP() << "no pdftoppm";
  const Checked checked = check_printed_colours(out.dir, [&](const Vec3& p) -> std::optional<Rgb> {
    const double r = std::hypot(p.x(), p.y());
    if (std::abs(p.z()) > 0.97) {  // a cap, away from its rim
      if (r > 0.9) return std::nullopt;
      return p.z() > 0 ? kTop : kBottom;
    }
    if (std::abs(p.z()) > 0.9 || r < 0.95) return std::nullopt;
    const double band = 4 * angle_u(p);
    if (std::abs(band - std::round(band)) < 0.08) return std::nullopt;  // a band boundary
    return kBands[static_cast<int>(band) % 4];
  });
  EXPECT_GT(checked.sampled, 50) << checked;
  EXPECT_GE(checked.matching, 0.99 * checked.sampled) << checked;
  std::cout << "[ colours  ] " << checked << "\n";
}

// A PLY whose faces carry colours (by the side they face): printed as they are.
TEST(Texture, PlyFaceColoursArePrinted) {
  const auto dir = testing::fresh_temp_dir("ply_colours");
  const TriangleMesh sphere = generate_shape("sphere", {{"subdivisions", 3}});
  auto colour_of = [](const Vec3& n) {
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
    return kSideColours[2 * axis + (n[axis] > 0 ? 1 : 0)];
  };
  std::ofstream ply(dir / "ball.ply");
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << sphere.vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
      << sphere.triangles.size()
      << "\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\n"
         "property uchar blue\nend_header\n";
  for (const Vec3& p : sphere.vertices) ply << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : sphere.triangles) {
    const Vec3 centre = (sphere.vertices[t[0]] + sphere.vertices[t[1]] + sphere.vertices[t[2]]) / 3;
    const Rgb c = colour_of(centre);
    ply << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << c.r << ' ' << c.g << ' ' << c.b
        << '\n';
  }
  ply.close();
  const auto out = run_file(dir / "ball.ply", "2%");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  if (std::system("command -v pdftoppm > /dev/null 2>&1") != 0) GTEST_SKIP() << "no pdftoppm";
  const Checked checked = check_printed_colours(out.dir, [&](const Vec3& p) -> std::optional<Rgb> {
    // The input face nearest p (brute force), unless a face of another colour is nearly as
    // near (the printed boundary is only as sharp as the pixels).
    double best = 1e300;
    Rgb colour{0, 0, 0};
    std::vector<std::pair<double, Rgb>> by_face;
    for (const Triangle& t : sphere.triangles) {
      const Vec3 centre =
          (sphere.vertices[t[0]] + sphere.vertices[t[1]] + sphere.vertices[t[2]]) / 3;
      const double d = testing::reference_triangle_distance(
          p, sphere.vertices[t[0]], sphere.vertices[t[1]], sphere.vertices[t[2]]);
      by_face.push_back({d, colour_of(centre)});
      if (d < best) best = d, colour = by_face.back().second;
    }
    for (const auto& [d, c] : by_face)
      if ((c.r != colour.r || c.g != colour.g || c.b != colour.b) && d < best + 0.04)
        return std::nullopt;
    return colour;
  });
  EXPECT_GT(checked.sampled, 50) << checked;
  EXPECT_GE(checked.matching, 0.99 * checked.sampled) << checked;
  std::cout << "[ colours  ] " << checked << "\n";
}

// A texture that does not exist: a warning naming the file and the material, and the pattern.
TEST(Texture, MissingTextureIsAWarningAndThePatternIsPrinted) {
  const auto dir = testing::fresh_temp_dir("missing_texture");
  std::ofstream(dir / "tube.mtl") << "newmtl skin\nmap_Kd nowhere.png\n";
  const TriangleMesh tube = open_cylinder();
  std::ofstream obj(dir / "tube.obj");
  obj << "mtllib tube.mtl\nusemtl skin\n";
  for (const Vec3& p : tube.vertices) obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Vec3& p : tube.vertices)
    obj << "vt " << 0.5 * (p.x() + 1.0) << ' ' << 0.5 * p.z() << '\n';
  for (const Triangle& t : tube.triangles)
    obj << "f " << t[0] + 1 << '/' << t[0] + 1 << ' ' << t[1] + 1 << '/' << t[1] + 1 << ' '
        << t[2] + 1 << '/' << t[2] + 1 << '\n';
  obj.close();
  const auto out = run_file(dir / "tube.obj", "2%");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  EXPECT_TRUE(std::filesystem::exists(out.dir / "pattern.pdf"));
  const std::string notes = out.report.at("notes").dump();
  EXPECT_NE(notes.find("nowhere.png"), std::string::npos) << notes;
  EXPECT_NE(notes.find("'skin'"), std::string::npos) << notes;
}

}  // namespace
}  // namespace papercraft
