#pragma once
// Flat strips read back from JSON in strips.json's layout (id, source_strip, vertices3d,
// vertices2d, triangles and, where present, boundary): a run's output, or a test fixture.

#include <nlohmann/json.hpp>
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

}  // namespace papercraft::testing
