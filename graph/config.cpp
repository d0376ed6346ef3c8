#include "graph/config.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "core/errors.h"
#include "graph/default_config.h"

namespace papercraft {

int PipelineConfig::find_node(const std::string& name) const {
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

const std::string& default_config_text() {
  static const std::string text = kDefaultConfigYaml;
  return text;
}

namespace {

ConfigMark mark_of(const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  return {m.line + 1, m.column + 1};
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

class Parser {
 public:
  Parser(const std::string& file, const Registry& registry) : file_(file), registry_(registry) {}

  [[noreturn]] void fail(ConfigMark mark, const std::string& message) const {
    throw ConfigException(file_ + ":" + std::to_string(mark.line) + ":" +
                          std::to_string(mark.column) + ": " + message);
  }
  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const {
    fail(mark_of(node), message);
  }

  // Checks a map's keys: no duplicates, only `allowed`, every one of `required` present.
  void check_keys(const YAML::Node& map, const std::string& what,
                  const std::vector<std::string>& allowed,
                  const std::vector<std::string>& required) const {
    if (!map.IsMap()) fail(map, "expected a map for " + what);
    std::set<std::string> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
      if (!it->first.IsScalar()) fail(it->first, "expected a key (a name) in " + what);
      const std::string key = it->first.Scalar();
      if (!seen.insert(key).second) fail(it->first, "duplicate key '" + key + "' in " + what);
      if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        fail(it->first,
             "unknown key '" + key + "' in " + what + " (expected one of " + join(allowed) + ")");
      }
    }
    for (const auto& key : required) {
      if (!seen.count(key)) fail(map, "missing key '" + key + "' in " + what);
    }
  }

  std::string scalar(const YAML::Node& node, const std::string& what) const {
    if (!node.IsScalar()) fail(node, "expected " + what);
    return node.Scalar();
  }

  // The `effort:` map: each weight a number >= 0 (core/effort.h), unknown keys refused.
  EffortWeights effort_weights(const YAML::Node& map) const {
    EffortWeights weights;
    const std::pair<const char*, double*> keys[] = {
        {"piece", &weights.piece},
        {"seam", &weights.seam},
        {"glue_per_metre", &weights.glue_per_metre},
        {"sawtooth", &weights.sawtooth},
        {"small_piece", &weights.small_piece},
        {"narrow_piece", &weights.narrow_piece}};
    std::vector<std::string> names;
    for (const auto& key : keys) names.push_back(key.first);
    if (!map.IsMap()) fail(map, "effort: expected a map of weights (" + join(names) + ")");
    check_keys(map, "effort", names, {});
    for (const auto& [name, target] : keys) {
      const YAML::Node node = map[name];
      if (!node) continue;
      const std::string text = scalar(node, std::string("a number for effort.") + name);
      double number = 0.0;
      const std::size_t used = parse_number_prefix(text, number);
      if (used == 0 || used != text.size() || !std::isfinite(number))
        fail(node, std::string("effort.") + name + ": expected a number, got '" + text + "'");
      if (number < 0.0)
        fail(node, std::string("effort.") + name + " must be at least 0, got " + text);
      *target = number;
    }
    return weights;
  }

  PipelineConfig parse(const std::string& text) {
    PipelineConfig config;
    config.file = file_;
    config.text = text;
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      fail(ConfigMark{e.mark.line + 1, e.mark.column + 1}, "invalid YAML: " + e.msg);
    }
    if (!root.IsDefined() || root.IsNull()) fail(ConfigMark{1, 1}, "the configuration is empty");
    check_keys(root, "the configuration",
               {"description", "tolerance", "threads", "height_mm", "scale", "min_width_mm",
                "min_area_mm2", "effort", "nodes"},
               {"nodes"});
    auto paper = [&](const char* key, bool zero_ok, const std::string& meaning) {
      std::optional<double> value;
      const YAML::Node node = root[key];
      if (!node) return value;
      const std::string text = scalar(node, meaning);
      double number = 0.0;
      const std::size_t used = parse_number_prefix(text, number);
      if (used == 0 || used != text.size() || !std::isfinite(number))
        fail(node, std::string(key) + ": expected a number (" + meaning + "), got '" + text + "'");
      if (zero_ok ? number < 0.0 : number <= 0.0)
        fail(node, std::string(key) + " must be " + (zero_ok ? "at least 0" : "greater than 0") +
                       " (" + meaning + "), got " + text);
      value = number;
      return value;
    };
    config.height_mm = paper("height_mm", false, "the model's largest side on paper, in mm");
    config.scale = paper("scale", false, "mm on paper per model unit");
    config.min_width_mm = paper("min_width_mm", true, "the narrowest piece, in mm; 0: no bound");
    config.min_area_mm2 = paper("min_area_mm2", true, "the smallest piece, in mm^2; 0: no bound");
    if (const YAML::Node effort = root["effort"]) config.effort = effort_weights(effort);
    if (root["tolerance"]) {
      try {
        config.tolerance = parse_tolerance(scalar(root["tolerance"], "a tolerance like 2%"));
      } catch (const std::invalid_argument& e) {
        fail(root["tolerance"], e.what());
      }
    }
    if (root["threads"]) {
      const YAML::Node threads = root["threads"];
      try {
        config.threads = std::stoi(scalar(threads, "a thread count"));
      } catch (const std::logic_error&) {
        fail(threads, "expected a thread count (0 = all cores), got '" + threads.Scalar() + "'");
      }
      if (*config.threads < 0) fail(threads, "expected a thread count >= 0");
    }
    const YAML::Node nodes = root["nodes"];
    check_keys(nodes, "nodes", {}, {});
    if (nodes.size() == 0) fail(nodes, "expected at least one node under 'nodes'");
    std::vector<YAML::Node> node_maps;
    for (auto it = nodes.begin(); it != nodes.end(); ++it) {
      NodeConfig node;
      node.name = it->first.Scalar();
      node.mark = mark_of(it->first);
      const YAML::Node body = it->second;
      check_keys(body, "node '" + node.name + "'", {"impl", "params", "to", "back", "concurrency"},
                 {"impl"});
      node.impl = scalar(body["impl"], "an implementation name like hausdorff.bounded");
      const NodeSpec* spec = registry_.find(node.impl);
      if (!spec) {
        fail(body["impl"], "unknown node implementation '" + node.impl +
                               "' (known: " + join(registry_.names()) + ")");
      }
      node.params = parse_params(body["params"], *spec, node.name, body);
      if (body["concurrency"]) {
        try {
          node.concurrency = std::stoi(scalar(body["concurrency"], "a concurrency"));
        } catch (const std::logic_error&) {
          fail(body["concurrency"], "expected a concurrency (0 = unlimited)");
        }
        if (node.concurrency < 0) fail(body["concurrency"], "expected a concurrency >= 0");
      }
      config.nodes.push_back(std::move(node));
      node_maps.push_back(body);
    }
    for (std::size_t i = 0; i < config.nodes.size(); ++i) {
      parse_edges(config, static_cast<int>(i), node_maps[i]["to"], false);
      parse_edges(config, static_cast<int>(i), node_maps[i]["back"], true);
    }
    check_graph(config);
    return config;
  }

 private:
  Params parse_params(const YAML::Node& params, const NodeSpec& spec, const std::string& node,
                      const YAML::Node& body) const {
    std::map<std::string, ParamValue> values;
    for (const ParamSpec& p : spec.params) {
      values[p.name] = parse_param_value(p, p.default_value);
    }
    if (!params) return Params(std::move(values));
    std::vector<std::string> known;
    for (const ParamSpec& p : spec.params) known.push_back(p.name);
    check_keys(params, "params of node '" + node + "'", {}, {});
    for (auto it = params.begin(); it != params.end(); ++it) {
      const std::string key = it->first.Scalar();
      auto p = std::find_if(spec.params.begin(), spec.params.end(),
                            [&](const ParamSpec& s) { return s.name == key; });
      if (p == spec.params.end()) {
        fail(it->first, "unknown parameter '" + key + "' for " + spec.name +
                            (known.empty() ? " (it takes none)" : " (known: " + join(known) + ")"));
      }
      std::string text;
      if (it->second.IsScalar()) {
        text = it->second.Scalar();
      } else if (it->second.IsSequence()) {
        text = "[";
        for (std::size_t k = 0; k < it->second.size(); ++k) {
          text += (k ? ", " : "") + scalar(it->second[k], "a list of scalars");
        }
        text += "]";
      } else {
        fail(it->second,
             "expected a " + std::string(to_string(p->type)) + " for parameter '" + key + "'");
      }
      try {
        values[key] = parse_param_value(*p, text);
      } catch (const std::invalid_argument& e) {
        fail(it->second, "parameter '" + key + "' of node '" + node + "': " + e.what());
      }
    }
    return Params(std::move(values));
  }

  void add_edge(PipelineConfig& config, int from, int port, const YAML::Node& target,
                bool back) const {
    const std::string name = scalar(target, "a node name");
    const int to = config.find_node(name);
    if (to < 0) fail(target, "edge to unknown node '" + name + "'");
    const NodeSpec& from_spec = *registry_.find(config.nodes[from].impl);
    const NodeSpec& to_spec = *registry_.find(config.nodes[to].impl);
    const MessageType& sent = from_spec.outputs[port].type;
    if (sent.type != to_spec.input.type) {
      fail(target, "type mismatch on edge " + config.nodes[from].name + "." +
                       from_spec.outputs[port].name + " -> " + name + ": " +
                       config.nodes[from].name + " (" + from_spec.name + ") emits " + sent.name +
                       " but " + name + " (" + to_spec.name + ") takes " + to_spec.input.name);
    }
    config.edges.push_back({from, port, to, back, mark_of(target)});
  }

  void parse_edges(PipelineConfig& config, int from, const YAML::Node& edges, bool back) const {
    if (!edges) return;
    const std::string key = back ? "back" : "to";
    const NodeSpec& spec = *registry_.find(config.nodes[from].impl);
    const std::string& node = config.nodes[from].name;
    if (spec.outputs.empty()) {
      fail(edges, "node '" + node + "' (" + spec.name + ") has no outputs, so no '" + key + "'");
    }
    auto targets = [&](const YAML::Node& list, int port) {
      if (list.IsScalar()) return add_edge(config, from, port, list, back);
      if (!list.IsSequence()) fail(list, "expected a list of node names");
      for (std::size_t k = 0; k < list.size(); ++k) add_edge(config, from, port, list[k], back);
    };
    if (spec.outputs.size() == 1) {
      if (edges.IsMap()) {
        fail(edges, "node '" + node + "' has a single output: expected '" + key +
                        ": [node, ...]', not a map of ports");
      }
      targets(edges, 0);
      return;
    }
    std::vector<std::string> ports;
    for (const auto& p : spec.outputs) ports.push_back(p.name);
    if (!edges.IsMap()) {
      fail(edges, "node '" + node + "' (" + spec.name + ") has outputs " + join(ports) +
                      ": expected '" + key + ": {" + ports[0] + ": [node, ...], ...}'");
    }
    check_keys(edges, "'" + key + "' of node '" + node + "'", ports, {});
    for (std::size_t port = 0; port < ports.size(); ++port) {
      if (edges[ports[port]]) targets(edges[ports[port]], static_cast<int>(port));
    }
  }

  void check_graph(PipelineConfig& config) const {
    const std::size_t n = config.nodes.size();
    std::vector<int> fed(n, 0);
    for (const auto& e : config.edges) fed[e.to]++;
    for (std::size_t i = 0; i < n; ++i) {
      const NodeSpec& spec = *registry_.find(config.nodes[i].impl);
      if (spec.input.name == "Job") {
        if (config.entry >= 0) {
          fail(config.nodes[i].mark, "two nodes take Job (" + config.nodes[config.entry].name +
                                         " and " + config.nodes[i].name + "): expected one loader");
        }
        config.entry = static_cast<int>(i);
      } else if (fed[i] == 0) {
        fail(config.nodes[i].mark, "node '" + config.nodes[i].name +
                                       "' is fed by no other node (add it to some node's 'to')");
      }
    }
    if (config.entry < 0) {
      fail(ConfigMark{1, 1}, "no node takes Job: expected a loader such as load.openmesh");
    }
    // Forward edges must form a DAG; a loop must be closed by an edge marked `back`.
    std::vector<int> state(n, 0);  // 0 new, 1 on stack, 2 done
    std::vector<int> stack;
    std::function<void(int)> visit = [&](int v) {
      state[v] = 1;
      stack.push_back(v);
      for (const auto& e : config.edges) {
        if (e.back || e.from != v) continue;
        if (state[e.to] == 1) {
          std::string cycle;
          auto start = std::find(stack.begin(), stack.end(), e.to);
          for (auto it = start; it != stack.end(); ++it) cycle += config.nodes[*it].name + " -> ";
          cycle += config.nodes[e.to].name;
          fail(e.mark, "cycle " + cycle +
                           " without a marked back edge (list the edge that closes the loop "
                           "under 'back:' instead of 'to:')");
        }
        if (state[e.to] == 0) visit(e.to);
      }
      stack.pop_back();
      state[v] = 2;
    };
    for (std::size_t i = 0; i < n; ++i) {
      if (state[i] == 0) visit(static_cast<int>(i));
    }
  }

  std::string file_;
  const Registry& registry_;
};

}  // namespace

PipelineConfig parse_pipeline_config(const std::string& text, const std::string& file,
                                     const Registry& registry) {
  return Parser(file, registry).parse(text);
}

PipelineConfig load_pipeline_config(const std::filesystem::path& path, const Registry& registry) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IOException(path.string() + ": cannot read the configuration file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_pipeline_config(text.str(), path.string(), registry);
}

}  // namespace papercraft
