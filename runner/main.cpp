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
#include "core/printable_utf8.h"
#include "graph/config.h"
#include "graph/params.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "runner/batch_job.h"
#include "runner/progress_display.h"
#include "runner/run_models.h"
#include "runner/stop_signals.h"
#include "runner/summary_command.h"

namespace papercraft {
namespace {

struct CommonOptions {
  bool verbose = false;
  bool quiet = false;
};

// A numeric option's range, said as a person says it ("must be at least 1, got -1") rather
// than CLI11's ranges, which print the largest double in full.
CLI::Validator number_at_least(double minimum, bool exclusive = false) {
  const std::string bound = (exclusive ? "greater than " : "at least ") + format_number(minimum);
  return CLI::Validator(
      [minimum, exclusive, bound](std::string& text) -> std::string {
        double value = 0.0;
        if (parse_number_prefix(text, value) != text.size() || text.empty()) {
          return "expected a number, got '" + text + "'";
        }
        const bool ok = exclusive ? value > minimum : value >= minimum;
        return ok ? std::string() : "must be " + bound + ", got " + text;
      },
      "NUMBER " + bound);
}

void setup_logging(const CommonOptions& common, ProgressDisplay& display) {
  auto sink = display.wrap(std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
  auto logger = std::make_shared<spdlog::logger>("papercraft", sink);
  logger->set_pattern("%^[%l]%$ %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(common.verbose ? spdlog::level::debug
                    : common.quiet ? spdlog::level::warn
                                   : spdlog::level::info);
}

// `batch JOB --list`: the inputs this shard runs and their output folders.
void list_inputs(const RunRequest& request) {
  for (std::size_t i = 0; i < request.inputs.size(); ++i) {
    std::cout << printable_utf8(request.names[i]) << "\t"
              << printable_utf8(request.inputs[i].string()) << "\t"
              << printable_utf8((request.output / request.names[i]).string()) << "\n";
  }
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

// `papercraft run`: its options as parsed.
struct RunCommand {
  CLI::App* command = nullptr;
  RunRequest request;
  std::vector<std::string> inputs;
  std::string tolerance_text, height_text, min_width_text;
  double scale = 0.0, min_area = 0.0;
  int max_pages = 0;
  CLI::Option *scale_option = nullptr, *min_area_option = nullptr, *max_pages_option = nullptr;
};

void add_run_command(CLI::App& app, RunCommand& run_command) {
  RunRequest& run_request = run_command.request;
  auto* run = app.add_subcommand(
      "run", "run the pipeline on mesh files (OBJ, OFF, PLY, STL, glTF/GLB, 3MF)");
  run_command.command = run;
  run->add_option("meshes", run_command.inputs, "input meshes")->required();
  run->add_option("-c,--config", run_request.config_file, "pipeline YAML (default: builtin)");
  run->add_option("-t,--tolerance", run_command.tolerance_text,
                  "Hausdorff tolerance: 2% of the largest side, or absolute like 0.004");
  run->add_option("-o,--out", run_request.output, "output folder (default: out)");
  run->add_option("-j,--threads", run_request.threads, "worker threads, 0 = all cores")
      ->check(number_at_least(0));
  run->add_option("--grace", run_request.grace_seconds,
                  "after SIGINT/SIGTERM, seconds the running models may take to finish before "
                  "they are abandoned (default 10)")
      ->check(number_at_least(0));
  auto* height = run->add_option("--height", run_command.height_text,
                                 "size of the model's largest side on paper: 200, 200mm, 20cm, "
                                 "8in (a bare number is mm)");
  run_command.scale_option =
      run->add_option("--scale", run_command.scale, "mm on paper per model unit")
          ->check(number_at_least(0, /*exclusive=*/true))
          ->excludes(height);
  run->add_option("--min-width", run_command.min_width_text,
                  "no piece narrower than this on paper, but for its tips: 5, 5mm, 0.5cm "
                  "(0: no bound; default 5 mm)");
  run_command.min_area_option =
      run->add_option("--min-area", run_command.min_area,
                      "no piece smaller than this many mm^2 on paper (0: no bound; default 100)")
          ->check(number_at_least(0));
  run_command.max_pages_option =
      run->add_option("--max-pages", run_command.max_pages,
                      "refuse a model whose pattern would need more pages than this, estimated "
                      "from its surface area at the print scale (default 100)")
          ->check(number_at_least(1));
  run->add_flag("--allow-large-tolerance", run_request.allow_large_tolerance,
                "accept a tolerance above 50% of the model's largest side");
}

int run_command(RunCommand& run_command, ProgressDisplay& display) {
  RunRequest& run_request = run_command.request;
  for (const auto& input : run_command.inputs) run_request.inputs.emplace_back(input);
  if (!run_command.tolerance_text.empty())
    run_request.tolerance = parse_tolerance_option(run_command.tolerance_text);
  if (!run_command.height_text.empty()) {
    try {
      run_request.height_mm = parse_length_mm(run_command.height_text);
    } catch (const std::invalid_argument& e) {
      throw InvalidInputException(std::string("--height: ") + e.what());
    }
  }
  if (*run_command.scale_option) run_request.scale = run_command.scale;
  if (!run_command.min_width_text.empty()) {
    try {
      run_request.min_width_mm =
          run_command.min_width_text == "0" ? 0.0 : parse_length_mm(run_command.min_width_text);
    } catch (const std::invalid_argument& e) {
      throw InvalidInputException(std::string("--min-width: ") + e.what());
    }
  }
  if (*run_command.min_area_option) run_request.min_area_mm2 = run_command.min_area;
  if (*run_command.max_pages_option) run_request.max_pages = run_command.max_pages;
  run_request.names = unique_model_names(run_request.inputs);
  return run_models(run_request, display);
}

// `papercraft batch`: its options as parsed.
struct BatchCommand {
  CLI::App* command = nullptr;
  std::string job_file, shard;
  int threads = -1, max_pages = 0;
  bool force = false, list = false, allow_large_tolerance = false;
  double grace = 10.0;
  CLI::Option* max_pages_option = nullptr;
};

void add_batch_command(CLI::App& app, BatchCommand& batch_command) {
  auto* batch = app.add_subcommand("batch", "run a batch job file (YAML: inputs, output, ...)");
  batch_command.command = batch;
  batch->add_option("job", batch_command.job_file, "job YAML")->required();
  batch->add_option("-j,--threads", batch_command.threads, "override the job's thread count")
      ->check(number_at_least(0));
  batch->add_option("--shard", batch_command.shard,
                    "run shard I of N (like 2/4: inputs 2, 6, 10, ...); overrides the job's");
  batch->add_flag("--force", batch_command.force,
                  "run every model again, also those an earlier run finished with the same "
                  "input and settings");
  batch
      ->add_option("--grace", batch_command.grace,
                   "after SIGINT/SIGTERM, seconds the running models may take to finish "
                   "before they are abandoned (default 10)")
      ->check(number_at_least(0));
  batch->add_flag("--list", batch_command.list,
                  "print the models this shard would run (name, input file, output folder; "
                  "tab-separated) and exit");
  batch_command.max_pages_option =
      batch
          ->add_option("--max-pages", batch_command.max_pages,
                       "refuse a model whose pattern would need more pages than this "
                       "(default 100)")
          ->check(number_at_least(1));
  batch->add_flag("--allow-large-tolerance", batch_command.allow_large_tolerance,
                  "accept a tolerance above 50% of a model's largest side");
}

int batch_command(const BatchCommand& batch, ProgressDisplay& display) {
  const BatchJob job = load_batch_job(batch.job_file);
  Shard shard{job.shard_index, job.shard_count};
  if (!batch.shard.empty()) {
    try {
      shard = parse_shard(batch.shard);
    } catch (const std::invalid_argument& e) {
      throw InvalidInputException(std::string("--shard: ") + e.what());
    }
  }
  RunRequest request;
  request.kind = RunRequest::Kind::kBatch;
  // Names over the whole job, so that shards never share an output folder.
  const std::vector<std::string> names = unique_model_names(job.inputs);
  for (const std::size_t i : shard_indices(job.inputs.size(), shard.index, shard.count)) {
    request.inputs.push_back(job.inputs[i]);
    request.names.push_back(names[i]);
  }
  request.shard_index = shard.index;
  request.shard_count = shard.count;
  if (job.config) request.config_file = job.config->string();
  request.tolerance = job.tolerance;
  request.output = job.output;
  request.threads = batch.threads >= 0 ? batch.threads : job.threads.value_or(-1);
  request.height_mm = job.height_mm;
  request.min_width_mm = job.min_width_mm;
  request.min_area_mm2 = job.min_area_mm2;
  request.force = batch.force;
  if (*batch.max_pages_option) request.max_pages = batch.max_pages;
  request.allow_large_tolerance = batch.allow_large_tolerance;
  request.grace_seconds = batch.grace;
  if (batch.list) {
    list_inputs(request);
    return kExitOk;
  }
  if (shard.count > 1) {
    spdlog::info("shard {}/{}: {} of {} inputs", shard.index + 1, shard.count,
                 request.inputs.size(), job.inputs.size());
  }
  return run_models(request, display);
}

int validate_command(const std::string& validate_file) {
  const PipelineConfig config = load_pipeline_config(validate_file, builtin_registry());
  // Building each node checks what only the node knows (e.g. segment.fuzzy's alternatives).
  const Pipeline pipeline(config, builtin_registry());
  const NodeContext context{pipeline.refine_options()};
  for (const auto& node : config.nodes) {
    builtin_registry().find(node.impl)->create(node.params, context);
  }
  int back = 0;
  for (const auto& e : config.edges) back += e.back ? 1 : 0;
  std::cout << validate_file << ": ok (" << config.nodes.size() << " nodes, " << config.edges.size()
            << " edges, " << back << " back edge(s))\n";
  return kExitOk;
}

int generate_command(const std::string& shape, const std::filesystem::path& shape_out,
                     const std::vector<std::string>& shape_params, bool list_shapes) {
  if (list_shapes || shape.empty()) {
    for (const auto& name : shape_names()) {
      std::cout << name << "\n";
      for (const auto& p : shape_parameters(name)) {
        std::cout << "    " << p.name << " (default " << p.default_value << "): " << p.description
                  << "\n";
      }
    }
    return shape.empty() && !list_shapes ? kExitUsage : kExitOk;
  }
  if (shape_out.empty()) throw InvalidInputException("generate: missing the output file");
  return generate(shape, shape_out, shape_params);
}

int main_impl(int argc, char** argv) {
  CLI::App app{"papercraft: certified developable-strip paper patterns from triangle meshes"};
  app.set_version_flag("--version", PAPERCRAFT_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // -v/-q may follow the subcommand
  CommonOptions common;
  app.add_flag("-v,--verbose", common.verbose, "debug output on stderr");
  app.add_flag("-q,--quiet", common.quiet, "only warnings and errors on stderr");

  RunCommand run;
  add_run_command(app, run);
  BatchCommand batch;
  add_batch_command(app, batch);

  std::filesystem::path summary_dir;
  auto* summary = app.add_subcommand(
      "summary", "merge the batch, shard and run summaries of an output folder into batch.json");
  summary->add_option("out", summary_dir, "the output folder, or a job file (its output)")
      ->required();

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
  // Before any thread exists: SIGINT/SIGTERM are then taken by run_models' own thread.
  if (*run.command || *batch.command) block_stop_signals();
  ProgressDisplay display(
      {.enabled = !common.quiet && !batch.list, .terminal = ::isatty(STDERR_FILENO) == 1});
  setup_logging(common, display);
  omlog().disable();  // OpenMesh's chatter ("[OBJWriter] : write file"); errors come as ours
  omout().disable();

  try {
    if (*run.command) return run_command(run, display);
    if (*batch.command) return batch_command(batch, display);
    if (*summary) {
      const std::string extension = summary_dir.extension().string();
      std::error_code unreadable;
      const bool job = std::filesystem::is_regular_file(summary_dir, unreadable) &&
                       (extension == ".yaml" || extension == ".yml");
      return summary_command(job ? load_batch_job(summary_dir).output : summary_dir);
    }
    if (*nodes) {
      print_nodes(builtin_registry());
      return kExitOk;
    }
    if (*validate) return validate_command(validate_file);
    if (*gen) return generate_command(shape, shape_out, shape_params, list_shapes);
  } catch (const ConfigException& e) {
    spdlog::error("{}", printable_utf8(e.what()));
    return kExitUsage;
  } catch (const InvalidInputException& e) {
    spdlog::error("{}", printable_utf8(e.what()));
    return kExitUsage;
  } catch (const IOException& e) {
    spdlog::error("{}", printable_utf8(e.what()));
    return kExitUsage;
  } catch (const std::exception& e) {
    spdlog::critical("internal error: {}", printable_utf8(e.what()));
    return kExitInternal;
  }
  return kExitUsage;
}

}  // namespace
}  // namespace papercraft

int main(int argc, char** argv) {
  return papercraft::main_impl(argc, argv);
}
