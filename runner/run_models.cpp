#include "runner/run_models.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/page_size.h"
#include "core/printable_utf8.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "runner/batch_journal.h"
#include "runner/resume.h"
#include "runner/sha256.h"
#include "runner/stop_signals.h"

namespace papercraft {

namespace {

std::string format_number(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// The printable area of the layout node's page (its page and margin_mm), 0 without one.
double printable_page_area_mm2(const PipelineConfig& config) {
  for (const auto& node : config.nodes) {
    if (!node.params.has("page") || !node.params.has("margin_mm")) continue;
    const PageSize page = page_size_from_name(node.params.string("page"));
    const double margin = node.params.number("margin_mm");
    return std::max(0.0, page.width_mm - 2 * margin) * std::max(0.0, page.height_mm - 2 * margin);
  }
  return 0.0;
}

// The output folder, created, and a file written into it and removed: a folder no model can
// write is reported once here rather than by every model's first node that writes.
void require_writable_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) {
    throw IOException(printable_utf8(folder.string()) + ": cannot create folder: " + ec.message());
  }
  const std::filesystem::path probe = folder / (".write-test-" + std::to_string(::getpid()));
  std::FILE* file = std::fopen(probe.c_str(), "w");
  if (!file) {
    throw IOException(printable_utf8(folder.string()) + ": cannot write into the folder: " +
                      std::strerror(errno));
  }
  std::fclose(file);
  std::filesystem::remove(probe, ec);
}

}  // namespace

ToleranceSpec parse_tolerance_option(const std::string& text) {
  try {
    return parse_tolerance(text);
  } catch (const std::invalid_argument& e) {
    throw InvalidInputException(std::string("--tolerance: ") + e.what());
  }
}

std::shared_ptr<RunSettings> run_settings(const RunRequest& request, const PipelineConfig& config) {
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = request.tolerance.value_or(config.tolerance.value_or(ToleranceSpec{}));
  const ToleranceSpec& tolerance = settings->tolerance;
  if (tolerance.relative && tolerance.value > kLargestTolerance && !request.allow_large_tolerance) {
    const char* given = !request.tolerance                         ? "the config's tolerance "
                        : request.kind == RunRequest::Kind::kBatch ? "the job's tolerance "
                                                                   : "--tolerance ";
    throw InvalidInputException(
        given + tolerance.to_string() +
        " is above 50% of the largest side, where the strips no longer resemble the model; "
        "give a smaller tolerance or --allow-large-tolerance");
  }
  settings->allow_large_tolerance = request.allow_large_tolerance;
  if (request.max_pages) settings->max_pages = *request.max_pages;
  settings->page_area_mm2 = printable_page_area_mm2(config);
  settings->output_dir = request.output;
  settings->threads = request.threads >= 0 ? request.threads : config.threads.value_or(0);
  settings->config_file = config.file;
  settings->config_text = config.text;
  PaperSpec& paper = settings->paper;
  if (config.height_mm) paper.height_mm = *config.height_mm;
  if (config.scale) paper.scale = *config.scale;
  if (config.min_width_mm) paper.min_width_mm = *config.min_width_mm;
  if (config.min_area_mm2) paper.min_area_mm2 = *config.min_area_mm2;
  if (config.effort) settings->effort = *config.effort;
  if (request.height_mm) {
    paper.height_mm = *request.height_mm;
    paper.scale = 0.0;  // a height on the command line wins over a scale in the config
  }
  if (request.scale) paper.scale = *request.scale;
  if (request.min_width_mm) paper.min_width_mm = *request.min_width_mm;
  if (request.min_area_mm2) paper.min_area_mm2 = *request.min_area_mm2;
  return settings;
}

namespace {

// The line a model gets on stdout when it is recorded.
std::string result_line(const BatchRow& row) {
  switch (row.status) {
    case RowStatus::kOk:
      if (row.skipped) {
        return row.name + ": skipped, finished before from the same input and settings -> " +
               row.output + "/";
      }
      return row.name + ": ok, " + std::to_string(row.strips_3d) + " strips -> " +
             std::to_string(row.flat_strips) + " flat strips on " + std::to_string(row.pages) +
             " page(s), " + (row.certified ? "certified" : "UNCERTIFIED") +
             " error <= " + format_number("%.3g%%", row.hausdorff_bound_percent) +
             " of the largest side, " + format_number("%.3g", row.work_seconds) + " s of work, " +
             format_number("%.3g", row.wall_seconds) + " s wall -> " + row.output + "/";
    case RowStatus::kError:
      return row.name + ": ERROR " + row.error;
    case RowStatus::kInterrupted:
      return row.name + ": " + row.error;
    case RowStatus::kPending:
      break;
  }
  return row.name + ": pending";
}

// A model about to run must not look finished, nor keep the temporaries of a killed run.
void prepare_model_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return;
  std::filesystem::remove(folder / kFinishedRecord, ec);
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.size() > 1 && file[0] == '.' && file.find(".tmp-") != std::string::npos) {
      std::filesystem::remove(entry.path(), ec);
    }
  }
}

}  // namespace

int run_models(const RunRequest& request, ProgressDisplay& display) {
  const Registry& registry = builtin_registry();
  PipelineConfig config =
      request.config_file.empty()
          ? parse_pipeline_config(default_config_text(), "<builtin default.yaml>", registry)
          : load_pipeline_config(request.config_file, registry);
  const std::shared_ptr<RunSettings> settings = run_settings(request, config);
  const bool batch = request.kind == RunRequest::Kind::kBatch;
  const SummaryFiles files =
      batch ? batch_summary_files(request.output, request.shard_index, request.shard_count)
            : run_summary_files(request.output);
  const ResultKey key = result_key(*settings);
  require_writable_folder(request.output);

  // Rows in input order; the pipeline gets the ones to run.
  std::vector<BatchRow> rows;
  std::vector<std::filesystem::path> to_run;
  std::vector<std::string> to_run_names;
  std::vector<std::size_t> row_of;  // pipeline index -> row index
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < request.inputs.size(); ++i) {
    const std::filesystem::path folder = request.output / request.names[i];
    BatchRow row = pending_row(request.names[i], request.inputs[i]);
    if (batch && !request.force) {
      if (auto earlier = earlier_result(folder, request.inputs[i], key)) {
        earlier->name = row.name;
        earlier->input = row.input;
        earlier->output = printable_utf8(folder.string());
        rows.push_back(*earlier);
        ++skipped;
        continue;
      }
    }
    prepare_model_folder(folder);
    rows.push_back(row);
    row_of.push_back(i);
    to_run.push_back(request.inputs[i]);
    to_run_names.push_back(request.names[i]);
  }

  spdlog::info("{} model(s){}, tolerance {}, {} thread(s), output {}", request.inputs.size(),
               skipped > 0 ? " (" + std::to_string(skipped) + " done before: skipped)" : "",
               settings->tolerance.to_string(),
               settings->threads == 0 ? std::string("all") : std::to_string(settings->threads),
               printable_utf8(settings->output_dir.string()));

  JournalOptions journal_options;
  journal_options.files = files;
  if (request.shard_count > 1) {
    journal_options.shard =
        std::to_string(request.shard_index + 1) + "/" + std::to_string(request.shard_count);
  }
  journal_options.on_recorded = [&display, &request, &key](std::size_t index, const BatchRow& row) {
    if (row.status == RowStatus::kOk && !row.skipped) {
      // Last in the model's folder: a result is taken as finished only with this record.
      try {
        write_finished_record(request.output / request.names[index], row, key,
                              file_sha256_hex(request.inputs[index]));
      } catch (const std::exception& e) {
        spdlog::warn("{}: not resumable: {}", row.name, printable_utf8(e.what()));
      }
    }
    display.print(stdout, result_line(row));
  };
  BatchJournal journal(journal_options, rows);
  display.start(skipped);

  StopSignalOptions stop_options;
  stop_options.grace =
      std::chrono::milliseconds(static_cast<long>(std::max(0.0, request.grace_seconds) * 1000.0));
  stop_options.on_stop = [&display, &request](int signal) {
    const std::string text = "stopping (" + signal_name(signal) +
                             "): no new models; running ones may finish within " +
                             format_number("%g", request.grace_seconds) + " s";
    display.set_note("stopping (" + signal_name(signal) + ")");
    spdlog::warn("{}", text);
  };
  stop_options.on_abandon = [](int signal) {
    spdlog::warn("{}: abandoning the models still running", signal_name(signal));
  };
  stop_options.hard_exit = [&journal, &display, &files](int signal) {
    spdlog::warn("{}: node calls still running; exiting without them", signal_name(signal));
    journal.close(signal_name(signal));
    display.finish();
    std::fprintf(stdout, "interrupted by %s; summary in %s\n", signal_name(signal).c_str(),
                 printable_utf8(files.summary.string()).c_str());
    std::fflush(stdout);
    std::fflush(stderr);
    remove_temporary_files();
    ::_exit(128 + signal);
  };
  StopSignals stop(stop_options);

  PipelineOptions options;
  options.threads = settings->threads;
  options.names = to_run_names;
  options.stop_starting = stop.stop_starting();
  options.abandon = stop.abandon();
  options.progress_interval = display.interval();
  options.on_progress = [&display](const PipelineProgress& p) { display.update(p); };
  options.on_model_started = [&journal, &row_of](const ModelRun& model) {
    journal.started(row_of[model.index]);
  };
  const std::filesystem::path output = request.output;
  options.on_model_done = [&journal, &row_of, output](const ModelRun& model,
                                                      const ModelResult& result) {
    journal.record(row_of[model.index], row_from_result(result, output, unix_seconds_now()));
  };
  Pipeline pipeline(std::move(config), registry);
  const std::vector<ModelResult> results = pipeline.run(to_run, settings, options);
  stop.run_ended();
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (!results[i].started) {
      journal.record(row_of[i], row_from_result(results[i], output, unix_seconds_now()));
    }
  }
  const int signal = stop.signal();
  const BatchSummary summary = journal.close(signal ? signal_name(signal) : "");
  display.finish();

  const RowCounts counts = count_rows(summary.rows);
  const double wall = summary.finished_at - summary.started_at;
  bool internal = false;
  for (const ModelResult& r : results) internal = internal || r.internal_error;
  std::string line = std::to_string(counts.ok) + " passed";
  if (counts.skipped > 0) line += " (" + std::to_string(counts.skipped) + " skipped)";
  line += ", " + std::to_string(counts.failed) + " failed";
  if (counts.interrupted > 0) line += ", " + std::to_string(counts.interrupted) + " interrupted";
  line += " in " + format_number("%.1f", wall) + " s";
  if (counts.finished_here > 0 && wall > 0) {
    line += " (" + format_number("%.3g", 60.0 * counts.finished_here / wall) + " models/min)";
  }
  std::printf("%s; summary in %s\n", line.c_str(), printable_utf8(files.summary.string()).c_str());
  std::fflush(stdout);
  if (signal != 0) return 128 + signal;
  if (internal) {
    spdlog::critical(
        "internal error: a model failed on a bug of papercraft (see above); please "
        "report it");
    return kExitInternal;
  }
  return counts.failed > 0 ? kExitModelFailed : kExitOk;
}

}  // namespace papercraft
