// A run on a mesh given in memory that keeps its files in memory (what the Python module does)
// writes nothing and makes the same files as a run on the mesh written to disk.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/errors.h"
#include "core/generate.h"
#include "nodes/load/openmesh.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

// Runs the default pipeline at 2% on two threads into `out`: on `mesh` given in memory with
// keep_in_memory when `input` is empty, else on the file `input`. Returns the result and the
// files kept in memory (none from a run on a file).
std::pair<ModelResult, std::map<std::string, std::string>> run_model(
    const TriangleMesh& mesh, const std::filesystem::path& input, const std::filesystem::path& out,
    const std::string& name) {
  const Registry& registry = builtin_registry();
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = parse_tolerance("2%");
  settings->output_dir = out;
  settings->threads = 2;
  settings->config_text = default_config_text();
  settings->keep_in_memory = input.empty();
  Pipeline pipeline(parse_pipeline_config(default_config_text(), "test.yaml", registry), registry);
  PipelineOptions options;
  options.threads = 2;
  options.names = {name};
  if (input.empty()) options.meshes = {std::make_shared<const TriangleMesh>(mesh)};
  std::map<std::string, std::string> files;
  options.on_model_done = [&files](const ModelRun& model, const ModelResult&) {
    files = model.files();
  };
  ModelResult result = pipeline.run({input.empty() ? "<arrays>" : input}, settings, options).at(0);
  return {result, files};
}

// An OFF file of `mesh` with every coordinate to 17 significant digits (read back exactly).
void write_off(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  ASSERT_NE(out, nullptr);
  std::fprintf(out, "OFF\n%zu %zu 0\n", mesh.vertices.size(), mesh.triangles.size());
  for (const Vec3& p : mesh.vertices) std::fprintf(out, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  for (const Triangle& t : mesh.triangles) std::fprintf(out, "3 %d %d %d\n", t[0], t[1], t[2]);
  ASSERT_EQ(std::fclose(out), 0);
}

TEST(InMemory, WritesNothingAndMakesTheFilesOfARunOnDisk) {
  TorusOptions shape;
  shape.segments = 16;
  shape.tube_segments = 8;
  const TriangleMesh mesh = torus(shape);
  const auto scratch = testing::fresh_temp_dir("in_memory");
  const auto [result, files] = run_model(mesh, {}, scratch / "out", "torus");
  ASSERT_TRUE(result.ok) << result.error;
  EXPECT_FALSE(std::filesystem::exists(scratch / "out"));
  for (const char* name : {"report.json", "strips.json", "pieces.json", "approximation.obj",
                           "error.ply", "parts.ply", "pattern.pdf", "guide.png", "pattern-01.svg"})
    EXPECT_TRUE(files.count(name)) << name;
  EXPECT_EQ(files.at("pattern.pdf").rfind("%PDF-", 0), 0u);
  EXPECT_EQ(files.at("guide.png").substr(1, 3), "PNG");

  // The same mesh from a file, written to disk: the same strips, pieces and pages.
  write_off(mesh, scratch / "torus.off");
  const auto disk = run_model(mesh, scratch / "torus.off", scratch / "disk", "torus");
  ASSERT_TRUE(disk.first.ok) << disk.first.error;
  EXPECT_TRUE(disk.second.empty());
  const std::filesystem::path dir = scratch / "disk" / "torus";
  for (const char* name : {"strips.json", "pieces.json", "approximation.obj", "pattern-01.svg"})
    EXPECT_TRUE(files.at(name) == testing::read_text(dir / name)) << name << " differs";
  const auto report = nlohmann::json::parse(files.at("report.json"));
  const auto disk_report = nlohmann::json::parse(testing::read_text(dir / "report.json"));
  EXPECT_EQ(report["input"]["path"], "<arrays>");
  EXPECT_EQ(report["result"], disk_report["result"]);
}

TEST(InMemory, ArraysAreValidatedAsAFileIs) {
  TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                    {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
  EXPECT_EQ(load_arrays(mesh, "<arrays>").mesh.n_faces(), 4u);
  auto message = [](const TriangleMesh& bad) {
    try {
      load_arrays(bad, "<arrays>");
    } catch (const InvalidInputException& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  TriangleMesh nan = mesh;
  nan.vertices[3].z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message(nan).find("<arrays>: mesh has 1 vertex with non-finite coordinates"),
            std::string::npos)
      << message(nan);
  TriangleMesh out_of_range = mesh;
  out_of_range.triangles[2][1] = 9;
  EXPECT_NE(message(out_of_range).find("<arrays>"), std::string::npos);
  EXPECT_NE(message(out_of_range).find("out-of-range vertex indices"), std::string::npos)
      << message(out_of_range);
  EXPECT_NE(message(TriangleMesh{mesh.vertices, {}}).find("<arrays>: the mesh has no faces"),
            std::string::npos);
  // A model whose arrays fail fails alone, with the message.
  const auto scratch = testing::fresh_temp_dir("in_memory_bad");
  const auto [result, files] = run_model(nan, {}, scratch / "out", "bad");
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.error.find("non-finite"), std::string::npos) << result.error;
  EXPECT_FALSE(std::filesystem::exists(scratch / "out"));
}

}  // namespace
}  // namespace papercraft
