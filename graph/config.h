#pragma once
// The YAML pipeline configuration: which implementation runs each stage, with which
// parameters, and the edges between them. Parsing checks everything a user can get wrong
// and reports it as "file:line:column: what was expected" (ConfigException).
//
//   tolerance: 2%
//   threads: 0
//   height_mm: 200        # paper: the largest side printed this long (or scale: mm per unit)
//   min_width_mm: 5       # no piece narrower (but for its tips)
//   min_area_mm2: 100     # no piece smaller
//   nodes:
//     select:    {impl: select.geodesic, to: [ruled]}
//     hausdorff: {impl: hausdorff.bounded, params: {precision: 0.05},
//                 to: {accept: [unfold], reject: [cut]}}
//     cut:       {impl: cut.harmonic, back: [select]}   # `back` marks the loop's back edge

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/effort.h"
#include "graph/params.h"
#include "graph/registry.h"
#include "graph/tolerance.h"

namespace papercraft {

struct ConfigMark {
  int line = 0;  // 1-based
  int column = 0;
};

struct NodeConfig {
  std::string name;
  std::string impl;
  Params params;
  int concurrency = 0;  // 0: unlimited
  ConfigMark mark;
};

struct EdgeConfig {
  int from = -1;  // node index
  int port = 0;   // output port index of `from`
  int to = -1;    // node index
  bool back = false;
  ConfigMark mark;
};

struct PipelineConfig {
  std::string file;
  std::string text;
  std::optional<ToleranceSpec> tolerance;
  std::optional<int> threads;
  /// Paper: each key given in the config (height_mm, scale, min_width_mm, min_area_mm2).
  std::optional<double> height_mm, scale, min_width_mm, min_area_mm2;
  /// The `effort:` map: the assembly effort's weights (core/effort.h), each key optional.
  std::optional<EffortWeights> effort;
  std::vector<NodeConfig> nodes;
  std::vector<EdgeConfig> edges;
  int entry = -1;  // the node that takes Job

  int find_node(const std::string& name) const;
};

/// Parses and validates a config. `file` names the source in messages.
/// Throws ConfigException ("file:line:column: ...") on any error.
PipelineConfig parse_pipeline_config(const std::string& text, const std::string& file,
                                     const Registry& registry);

/// Reads a file and parses it. Throws IOException if unreadable, ConfigException if invalid.
PipelineConfig load_pipeline_config(const std::filesystem::path& path, const Registry& registry);

/// The text of configs/default.yaml, embedded at build time.
const std::string& default_config_text();

}  // namespace papercraft
