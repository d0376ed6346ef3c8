#include "runner/batch_job.h"

#include <glob.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/errors.h"

namespace papercraft {

std::vector<std::filesystem::path> expand_pattern(const std::string& pattern) {
  std::vector<std::filesystem::path> out;
  if (pattern.find_first_of("*?[") == std::string::npos) {
    std::error_code unreadable;  // a name too long, say: it matches nothing
    if (std::filesystem::exists(pattern, unreadable)) out.emplace_back(pattern);
    return out;
  }
  glob_t matches{};
  if (::glob(pattern.c_str(), 0, nullptr, &matches) == 0) {
    for (std::size_t i = 0; i < matches.gl_pathc; ++i) out.emplace_back(matches.gl_pathv[i]);
  }
  ::globfree(&matches);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::size_t> shard_indices(std::size_t input_count, int shard_index, int shard_count) {
  std::vector<std::size_t> out;
  for (std::size_t i = static_cast<std::size_t>(shard_index); i < input_count;
       i += static_cast<std::size_t>(shard_count)) {
    out.push_back(i);
  }
  return out;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto whole_number = [](const std::string& part) {
    if (part.empty() || part.size() > 9 ||
        part.find_first_not_of("0123456789") != std::string::npos) {
      throw std::invalid_argument("");
    }
    return std::stoi(part);
  };
  try {
    if (slash == std::string::npos) throw std::invalid_argument("");
    const int index = whole_number(text.substr(0, slash));
    const int count = whole_number(text.substr(slash + 1));
    if (count < 1 || index < 1 || index > count) throw std::invalid_argument("");
    return {index - 1, count};
  } catch (const std::logic_error&) {
    throw std::invalid_argument("expected a shard like 1/4 (the first of four), got '" + text +
                                "'");
  }
}

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const YAML::Node& node,
                       const std::string& message) {
  const YAML::Mark m = node.Mark();
  throw ConfigException(file.string() + ":" + std::to_string(m.line + 1) + ":" +
                        std::to_string(m.column + 1) + ": " + message);
}

std::string scalar(const std::filesystem::path& file, const YAML::Node& node,
                   const std::string& what) {
  if (!node.IsScalar()) fail(file, node, "expected " + what);
  return node.Scalar();
}

}  // namespace

BatchJob load_batch_job(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IOException(path.string() + ": cannot read the job file");
  std::ostringstream text;
  text << in.rdbuf();
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::ParserException& e) {
    throw ConfigException(path.string() + ":" + std::to_string(e.mark.line + 1) + ":" +
                          std::to_string(e.mark.column + 1) + ": invalid YAML: " + e.msg);
  }
  if (!root.IsMap()) fail(path, root, "expected a map with 'inputs' and 'output'");
  const std::vector<std::string> allowed = {"inputs",       "output",       "config",
                                            "tolerance",    "threads",      "height_mm",
                                            "min_width_mm", "min_area_mm2", "shard"};
  std::set<std::string> seen;
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (!seen.insert(key).second) fail(path, it->first, "duplicate key '" + key + "'");
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      fail(path, it->first,
           "unknown key '" + key +
               "' (expected inputs, output, config, tolerance, threads, height_mm, "
               "min_width_mm, min_area_mm2, shard)");
    }
  }
  if (!root["inputs"]) fail(path, root, "missing key 'inputs'");
  const std::filesystem::path base = path.parent_path();
  auto resolve = [&](const std::string& p) {
    const std::filesystem::path candidate(p);
    return candidate.is_absolute() ? candidate : base / candidate;
  };
  BatchJob job;
  YAML::Node inputs = root["inputs"];
  std::vector<YAML::Node> patterns;
  if (inputs.IsScalar()) {
    patterns.push_back(inputs);
  } else if (inputs.IsSequence()) {
    for (std::size_t i = 0; i < inputs.size(); ++i) patterns.push_back(inputs[i]);
  } else {
    fail(path, inputs, "expected a list of paths or glob patterns");
  }
  std::set<std::filesystem::path> unique;
  for (const auto& p : patterns) {
    const std::string pattern = resolve(scalar(path, p, "a path or glob pattern")).string();
    const auto matches = expand_pattern(pattern);
    if (matches.empty()) fail(path, p, "no file matches '" + pattern + "'");
    for (const auto& m : matches) {
      if (unique.insert(m.lexically_normal()).second) job.inputs.push_back(m.lexically_normal());
    }
  }
  if (root["output"]) job.output = resolve(scalar(path, root["output"], "an output folder"));
  if (root["config"]) job.config = resolve(scalar(path, root["config"], "a config file"));
  if (root["tolerance"]) {
    try {
      job.tolerance = parse_tolerance(scalar(path, root["tolerance"], "a tolerance"));
    } catch (const std::invalid_argument& e) {
      fail(path, root["tolerance"], e.what());
    }
  }
  auto number = [&](const char* key, double min) {
    const YAML::Node node = root[key];
    try {
      std::size_t used = 0;
      const std::string text = scalar(path, node, "a number");
      const double value = std::stod(text, &used);
      if (used != text.size() || value < min) throw std::invalid_argument("");
      return value;
    } catch (const std::logic_error&) {
      fail(path, node,
           std::string("expected a number >= ") + std::to_string(static_cast<int>(min)) + " for '" +
               key + "'");
    }
  };
  if (root["threads"]) {
    const double threads = number("threads", 0);
    if (threads > 100000 || threads != std::floor(threads))
      fail(path, root["threads"], "expected a whole number of threads from 0 to 100000");
    job.threads = static_cast<int>(threads);
  }
  if (root["height_mm"]) {
    job.height_mm = number("height_mm", 0);
    if (*job.height_mm <= 0) fail(path, root["height_mm"], "expected a height_mm > 0");
  }
  if (root["min_width_mm"]) job.min_width_mm = number("min_width_mm", 0);
  if (root["min_area_mm2"]) job.min_area_mm2 = number("min_area_mm2", 0);
  if (root["shard"]) {
    const std::string text = scalar(path, root["shard"], "a shard like 1/4");
    try {
      const Shard shard = parse_shard(text);
      job.shard_index = shard.index;
      job.shard_count = shard.count;
    } catch (const std::invalid_argument& e) {
      fail(path, root["shard"], e.what());
    }
  }
  return job;
}

}  // namespace papercraft
