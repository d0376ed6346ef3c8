#pragma once
// Runs the real pipeline in-process on generated meshes and reads its output files back,
// for end-to-end tests.

#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/mesh.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "support/temp_dir.h"

namespace papercraft::testing {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_mesh_file(const TriangleMesh& mesh, const std::filesystem::path& path) {
  const Mesh m = to_mesh(mesh);
  ASSERT_TRUE(OpenMesh::IO::write_mesh(m, path.string(), OpenMesh::IO::Options::Default, 17));
}

/// approximation.obj: one TriangleMesh per `g strip_<id>` group.
inline std::vector<TriangleMesh> read_strips_obj(const std::filesystem::path& path) {
  std::vector<TriangleMesh> strips;
  std::vector<Vec3> all;
  std::vector<int> owner_base;
  std::istringstream in(read_text(path));
  std::string line;
  int base = 0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string tag;
    row >> tag;
    if (tag == "g") {
      strips.emplace_back();
      base = static_cast<int>(all.size());
    } else if (tag == "v") {
      Vec3 p;
      row >> p.x() >> p.y() >> p.z();
      all.push_back(p);
      strips.back().vertices.push_back(p);
    } else if (tag == "f") {
      Triangle t;
      row >> t[0] >> t[1] >> t[2];
      for (int& i : t) i = i - 1 - base;
      strips.back().triangles.push_back(t);
    }
  }
  return strips;
}

inline TriangleMesh concatenate(const std::vector<TriangleMesh>& parts) {
  TriangleMesh all;
  for (const auto& p : parts) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), p.vertices.begin(), p.vertices.end());
    for (const Triangle& t : p.triangles)
      all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return all;
}

struct PipelineOutput {
  ModelResult result;
  std::filesystem::path dir;
  nlohmann::json report;
  std::vector<TriangleMesh> strips;  // from approximation.obj
  nlohmann::json flat;               // strips.json
};

/// Writes `mesh` to a temporary OBJ and runs the config (default: the builtin default) on it.
inline PipelineOutput run_pipeline(const TriangleMesh& mesh, const std::string& tolerance,
                                   const std::string& name, int threads = 0,
                                   const std::string& config_text = default_config_text(),
                                   const PaperSpec& paper = {}) {
  const auto dir = fresh_temp_dir(name);
  const auto input = dir / (name + ".obj");
  write_mesh_file(mesh, input);
  const Registry& registry = builtin_registry();
  PipelineConfig config = parse_pipeline_config(config_text, "test.yaml", registry);
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = parse_tolerance(tolerance);
  settings->output_dir = dir / "out";
  settings->threads = threads;
  settings->config_text = config_text;
  settings->paper = paper;
  Pipeline pipeline(std::move(config), registry);
  PipelineOptions options;
  options.threads = threads;
  auto results = pipeline.run({input}, settings, options);
  PipelineOutput out;
  out.result = results.at(0);
  out.dir = settings->output_dir / name;
  if (out.result.ok) {
    out.report = nlohmann::json::parse(read_text(out.dir / "report.json"));
    out.strips = read_strips_obj(out.dir / "approximation.obj");
    if (std::filesystem::exists(out.dir / "strips.json")) {
      out.flat = nlohmann::json::parse(read_text(out.dir / "strips.json"));
    }
  }
  return out;
}

}  // namespace papercraft::testing
