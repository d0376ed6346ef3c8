#pragma once
// Flat strips read back from JSON in strips.json's layout (id, source_strip, vertices3d,
// vertices2d, triangles and, where present, boundary): a run's output, or a test fixture.

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/strip.h"

namespace papercraft::testing {

inline std::vector<FlatStrip> read_flat_strips(const nlohmann::json& strips) {
  std::vector<FlatStrip> out;
  for (const auto& s : strips) {
    FlatStrip strip;
    strip.id = s.at("id").get<int>();
    strip.source_strip = s.at("source_strip").get<int>();
    for (const auto& p : s.at("vertices3d"))
      strip.vertices3d.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    for (const auto& p : s.at("vertices2d"))
      strip.vertices2d.emplace_back(p[0].get<double>(), p[1].get<double>());
    for (const auto& t : s.at("triangles"))
      strip.triangles.push_back({t[0].get<int>(), t[1].get<int>(), t[2].get<int>()});
    for (const auto& b : s.value("boundary", nlohmann::json::array())) {
      BoundaryEdge e;
      e.v0 = b.at("v0").get<int>();
      e.v1 = b.at("v1").get<int>();
      const std::string kind = b.at("kind").get<std::string>();
      e.kind = kind == "seam" ? EdgeKind::Seam : kind == "open" ? EdgeKind::Open : EdgeKind::Cut;
      e.label = b.value("label", std::string());
      e.neighbour_strip = b.value("neighbour", -1);
      e.partner_edge = b.value("partner_edge", -1);
      strip.boundary.push_back(e);
    }
    out.push_back(std::move(strip));
  }
  return out;
}

/// A finished run's flat strips (DIR/strips.json) and its print scale (report.json's paper
/// mm_per_unit); nullopt, with the reason on stderr after `tool`, where either file is missing.
struct RunStrips {
  std::vector<FlatStrip> strips;
  double mm_per_unit = 1.0;
};
inline std::optional<RunStrips> read_run_strips(const std::string& dir, const char* tool) {
  std::ifstream strips_file(dir + "/strips.json"), report_file(dir + "/report.json");
  if (!strips_file || !report_file) {
    std::fprintf(stderr, "%s: %s: no strips.json or report.json\n", tool, dir.c_str());
    return std::nullopt;
  }
  RunStrips run;
  run.mm_per_unit = nlohmann::json::parse(report_file).at("paper").at("mm_per_unit").get<double>();
  run.strips = read_flat_strips(nlohmann::json::parse(strips_file).at("strips"));
  return run;
}

}  // namespace papercraft::testing
