// papercraft — turns triangle meshes into paper patterns. See README.md for every command.

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/generate.h"
#include "core/mesh.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "runner/batch_job.h"

namespace papercraft {
namespace {

// Exit codes (README "Exit codes").
constexpr int kExitOk = 0;
constexpr int kExitModelFailed = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

struct CommonOptions {
  bool verbose = false;
  bool quiet = false;
};

void setup_logging(const CommonOptions& common) {
  auto logger = spdlog::stderr_color_mt("papercraft");
  logger->set_pattern("%^[%l]%$ %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(common.verbose ? spdlog::level::debug
                    : common.quiet ? spdlog::level::warn
                                   : spdlog::level::info);
}

std::string format_percent(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g%%", value);
  return buffer;
}

std::string batch_json(const std::vector<ModelResult>& results, const std::filesystem::path& out) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : results) {
    nlohmann::json row = {{"name", r.name},
                          {"input", r.input.string()},
                          {"status", r.ok ? "ok" : "error"},
                          {"seconds", r.wall_seconds}};
    if (!r.ok) row["error"] = r.error;
    if (r.ok) {
      row["output"] = (out / r.name).string();
      row["strips_3d"] = r.record.strips_3d;
      row["flat_strips"] = r.record.flat_strips;
      row["pages"] = r.record.pages;
      row["hausdorff_bound"] = r.record.hausdorff_bound;
      row["certified"] = r.record.certified;
    }
    rows.push_back(std::move(row));
  }
  long failed = 0;
  for (const auto& r : results) failed += r.ok ? 0 : 1;
  nlohmann::json root = {{"version", PAPERCRAFT_VERSION},
                         {"models", results.size()},
                         {"failed", failed},
                         {"results", rows}};
  return root.dump(2) + "\n";
}

struct RunRequest {
  std::vector<std::filesystem::path> inputs;
  std::string config_file;  // empty: builtin default
  std::string tolerance;    // empty: from the config
  std::filesystem::path output = "out";
  int threads = -1;  // -1: from the config
  // Paper: each set only when given (command line or job file); else the config's, else the
  // defaults of PaperSpec.
  std::optional<double> height_mm, scale, min_width_mm, min_area_mm2;
};

int execute(const RunRequest& request, const CommonOptions& common) {
  const Registry& registry = builtin_registry();
  PipelineConfig config =
      request.config_file.empty()
          ? parse_pipeline_config(default_config_text(), "<builtin default.yaml>", registry)
          : load_pipeline_config(request.config_file, registry);
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = config.tolerance.value_or(ToleranceSpec{});
  if (!request.tolerance.empty()) {
    try {
      settings->tolerance = parse_tolerance(request.tolerance);
    } catch (const std::invalid_argument& e) {
      throw InvalidInputException(std::string("--tolerance: ") + e.what());
    }
  }
  settings->output_dir = request.output;
  settings->threads = request.threads >= 0 ? request.threads : config.threads.value_or(0);
  settings->config_file = config.file;
  settings->config_text = config.text;
  PaperSpec& paper = settings->paper;
  if (config.height_mm) paper.height_mm = *config.height_mm;
  if (config.scale) paper.scale = *config.scale;
  if (config.min_width_mm) paper.min_width_mm = *config.min_width_mm;
  if (config.min_area_mm2) paper.min_area_mm2 = *config.min_area_mm2;
  if (request.height_mm) {
    paper.height_mm = *request.height_mm;
    paper.scale = 0.0;  // a height on the command line wins over a scale in the config
  }
  if (request.scale) paper.scale = *request.scale;
  if (request.min_width_mm) paper.min_width_mm = *request.min_width_mm;
  if (request.min_area_mm2) paper.min_area_mm2 = *request.min_area_mm2;

  PipelineOptions options;
  options.threads = settings->threads;
  if (!common.quiet) {
    options.on_progress = [](const PipelineProgress& p) {
      spdlog::info("progress: {}/{} models done, {} running", p.done, p.total, p.running.size());
    };
  }
  Pipeline pipeline(std::move(config), registry);
  spdlog::info("{} model(s), tolerance {}, {} thread(s), output {}", request.inputs.size(),
               settings->tolerance.to_string(),
               settings->threads == 0 ? std::string("all") : std::to_string(settings->threads),
               settings->output_dir.string());
  const auto results = pipeline.run(request.inputs, settings, options);
  write_file_atomic(settings->output_dir / "batch.json", batch_json(results, settings->output_dir));

  int failed = 0;
  bool internal = false;
  for (const auto& r : results) {
    if (r.ok) {
      const ModelRecord& record = r.record;
      const double largest = record.input.largest_side;
      std::cout << r.name << ": ok, " << record.strips_3d << " strips -> " << record.flat_strips
                << " flat strips on " << record.pages << " page(s), "
                << (record.certified ? "certified" : "UNCERTIFIED") << " error <= "
                << format_percent(largest > 0 ? 100 * record.hausdorff_bound / largest : 0)
                << " of the largest side, " << r.wall_seconds << " s -> "
                << (settings->output_dir / r.name).string() << "/\n";
    } else {
      ++failed;
      internal = internal || r.internal_error;
      std::cout << r.name << ": ERROR " << r.error << "\n";
    }
  }
  std::cout << results.size() - failed << " passed, " << failed << " failed; summary in "
            << (settings->output_dir / "batch.json").string() << "\n";
  if (internal) {
    spdlog::critical(
        "internal error: a model failed on a bug of papercraft (see above); please "
        "report it");
    return kExitInternal;
  }
  return failed > 0 ? kExitModelFailed : kExitOk;
}

void print_nodes(const Registry& registry) {
  for (const auto& [name, spec] : registry.specs()) {
    std::cout << name << "\n    " << spec.summary << "\n    input:  " << spec.input.name
              << (spec.gathers ? " (gathers all of a model's messages)" : "") << "\n";
    if (spec.outputs.empty()) std::cout << "    output: none (writes files)\n";
    for (const auto& port : spec.outputs) {
      std::cout << "    output: " << port.name << " -> " << port.type.name << "\n";
    }
    for (const auto& p : spec.params) {
      std::cout << "    param " << p.name << " (" << to_string(p.type) << ", default "
                << p.default_value << "): " << p.description;
      if (!p.choices.empty()) {
        std::cout << " [";
        for (std::size_t i = 0; i < p.choices.size(); ++i)
          std::cout << (i ? "|" : "") << p.choices[i];
        std::cout << "]";
      }
      std::cout << "\n";
    }
  }
}

int generate(const std::string& shape, const std::filesystem::path& out,
             const std::vector<std::string>& assignments) {
  std::map<std::string, double> parameters;
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos)
      throw InvalidInputException("--param expects NAME=VALUE, got '" + a + "'");
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(a.substr(eq + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != a.size() - eq - 1) {
      throw InvalidInputException("--param " + a + ": expected a number after '='");
    }
    parameters[a.substr(0, eq)] = value;
  }
  const Mesh mesh = to_mesh(generate_shape(shape, parameters));
  write_via_temporary(out, [&](const std::filesystem::path& temporary) {
    if (!OpenMesh::IO::write_mesh(mesh, temporary.string(), OpenMesh::IO::Options::Default, 17)) {
      throw IOException(out.string() + ": cannot write (use .obj, .off, .ply or .stl)");
    }
  });
  std::cout << out.string() << ": " << shape << ", " << mesh.n_vertices() << " vertices, "
            << mesh.n_faces() << " faces\n";
  return kExitOk;
}

int main_impl(int argc, char** argv) {
  CLI::App app{"papercraft: certified developable-strip paper patterns from triangle meshes"};
  app.set_version_flag("--version", PAPERCRAFT_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // -v/-q may follow the subcommand
  CommonOptions common;
  app.add_flag("-v,--verbose", common.verbose, "debug output on stderr");
  app.add_flag("-q,--quiet", common.quiet, "only warnings and errors on stderr");

  RunRequest run_request;
  std::vector<std::string> run_inputs;
  auto* run = app.add_subcommand("run", "run the pipeline on mesh files (OBJ, OFF, PLY, STL)");
  run->add_option("meshes", run_inputs, "input meshes")->required();
  run->add_option("-c,--config", run_request.config_file, "pipeline YAML (default: builtin)");
  run->add_option("-t,--tolerance", run_request.tolerance,
                  "Hausdorff tolerance: 2% of the largest side, or absolute like 0.004");
  run->add_option("-o,--out", run_request.output, "output folder (default: out)");
  run->add_option("-j,--threads", run_request.threads, "worker threads, 0 = all cores")
      ->check(CLI::NonNegativeNumber);
  std::string height_text;
  auto* height = run->add_option("--height", height_text,
                                 "size of the model's largest side on paper: 200, 200mm, 20cm, "
                                 "8in (a bare number is mm)");
  double scale = 0.0;
  auto* scale_option = run->add_option("--scale", scale, "mm on paper per model unit")
                           ->check(CLI::PositiveNumber)
                           ->excludes(height);
  std::string min_width_text;
  run->add_option("--min-width", min_width_text,
                  "no piece narrower than this on paper, but for its tips: 5, 5mm, 0.5cm "
                  "(0: no bound; default 5 mm)");
  double min_area = 0.0;
  auto* min_area_option =
      run->add_option("--min-area", min_area,
                      "no piece smaller than this many mm^2 on paper (0: no bound; default 100)")
          ->check(CLI::NonNegativeNumber);

  std::string job_file;
  auto* batch = app.add_subcommand("batch", "run a batch job file (YAML: inputs, output, ...)");
  batch->add_option("job", job_file, "job YAML")->required();
  int batch_threads = -1;
  batch->add_option("-j,--threads", batch_threads, "override the job's thread count");

  auto* nodes = app.add_subcommand("nodes", "list node implementations, ports and parameters");

  std::string validate_file;
  auto* validate = app.add_subcommand("validate", "check a pipeline config without running it");
  validate->add_option("config", validate_file, "pipeline YAML")->required();

  std::string shape;
  std::filesystem::path shape_out;
  std::vector<std::string> shape_params;
  bool list_shapes = false;
  auto* gen = app.add_subcommand("generate", "write an analytic test mesh");
  gen->add_option("shape", shape, "shape name (--list shows them)");
  gen->add_option("out", shape_out, "output mesh file (.obj, .off, .ply, .stl)");
  gen->add_option("-p,--param", shape_params, "shape parameter NAME=VALUE (repeatable)");
  gen->add_flag("--list", list_shapes, "list shapes and their parameters");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  setup_logging(common);
  omlog().disable();  // OpenMesh's chatter ("[OBJWriter] : write file"); errors come as ours
  omout().disable();

  try {
    if (*run) {
      for (const auto& input : run_inputs) run_request.inputs.emplace_back(input);
      if (!height_text.empty()) {
        try {
          run_request.height_mm = parse_length_mm(height_text);
        } catch (const std::invalid_argument& e) {
          throw InvalidInputException(std::string("--height: ") + e.what());
        }
      }
      if (*scale_option) run_request.scale = scale;
      if (!min_width_text.empty()) {
        try {
          run_request.min_width_mm = min_width_text == "0" ? 0.0 : parse_length_mm(min_width_text);
        } catch (const std::invalid_argument& e) {
          throw InvalidInputException(std::string("--min-width: ") + e.what());
        }
      }
      if (*min_area_option) run_request.min_area_mm2 = min_area;
      return execute(run_request, common);
    }
    if (*batch) {
      const BatchJob job = load_batch_job(job_file);
      RunRequest request;
      request.inputs = select_shard(job.inputs, job.shard_index, job.shard_count);
      if (job.config) request.config_file = job.config->string();
      if (job.tolerance) request.tolerance = job.tolerance->to_string();
      request.output = job.output;
      request.threads = batch_threads >= 0 ? batch_threads : job.threads.value_or(-1);
      request.height_mm = job.height_mm;
      request.min_width_mm = job.min_width_mm;
      request.min_area_mm2 = job.min_area_mm2;
      if (job.shard_count > 1) {
        spdlog::info("shard {}/{}: {} of {} inputs", job.shard_index + 1, job.shard_count,
                     request.inputs.size(), job.inputs.size());
      }
      return execute(request, common);
    }
    if (*nodes) {
      print_nodes(builtin_registry());
      return kExitOk;
    }
    if (*validate) {
      const PipelineConfig config = load_pipeline_config(validate_file, builtin_registry());
      // Building each node checks what only the node knows (e.g. segment.fuzzy's alternatives).
      const Pipeline pipeline(config, builtin_registry());
      const NodeContext context{pipeline.refine_options()};
      for (const auto& node : config.nodes) {
        builtin_registry().find(node.impl)->create(node.params, context);
      }
      int back = 0;
      for (const auto& e : config.edges) back += e.back ? 1 : 0;
      std::cout << validate_file << ": ok (" << config.nodes.size() << " nodes, "
                << config.edges.size() << " edges, " << back << " back edge(s))\n";
      return kExitOk;
    }
    if (*gen) {
      if (list_shapes || shape.empty()) {
        for (const auto& name : shape_names()) {
          std::cout << name << "\n";
          for (const auto& p : shape_parameters(name)) {
            std::cout << "    " << p.name << " (default " << p.default_value
                      << "): " << p.description << "\n";
          }
        }
        return shape.empty() && !list_shapes ? kExitUsage : kExitOk;
      }
      if (shape_out.empty()) throw InvalidInputException("generate: missing the output file");
      return generate(shape, shape_out, shape_params);
    }
  } catch (const ConfigException& e) {
    spdlog::error("{}", e.what());
    return kExitUsage;
  } catch (const InvalidInputException& e) {
    spdlog::error("{}", e.what());
    return kExitUsage;
  } catch (const IOException& e) {
    spdlog::error("{}", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    spdlog::critical("internal error: {}", e.what());
    return kExitInternal;
  }
  return kExitUsage;
}

}  // namespace
}  // namespace papercraft

int main(int argc, char** argv) {
  return papercraft::main_impl(argc, argv);
}
