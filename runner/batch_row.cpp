#include "runner/batch_row.h"

#include <chrono>
#include <stdexcept>

#include "core/printable_utf8.h"

namespace papercraft {

std::string to_string(RowStatus status) {
  switch (status) {
    case RowStatus::kOk:
      return "ok";
    case RowStatus::kError:
      return "error";
    case RowStatus::kInterrupted:
      return "interrupted";
    case RowStatus::kPending:
      return "pending";
  }
  return "pending";
}

RowStatus row_status_from_string(const std::string& text) {
  for (const RowStatus s :
       {RowStatus::kOk, RowStatus::kError, RowStatus::kInterrupted, RowStatus::kPending}) {
    if (to_string(s) == text) return s;
  }
  throw std::invalid_argument("unknown row status '" + printable_utf8(text) + "'");
}

double unix_seconds_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

BatchRow pending_row(const std::string& name, const std::filesystem::path& input) {
  BatchRow row;
  row.name = printable_utf8(name);
  row.input = printable_utf8(input.string());
  return row;
}

BatchRow row_from_result(const ModelResult& result, const std::filesystem::path& output_dir,
                         double finished_at) {
  BatchRow row = pending_row(result.name, result.input);
  if (!result.started) {
    row.status = RowStatus::kInterrupted;
    row.error = "interrupted before it started";
    return row;
  }
  row.work_seconds = result.work_seconds;
  row.wall_seconds = result.wall_seconds;
  row.queue_seconds = result.queue_seconds;
  row.started_at = finished_at - result.wall_seconds;
  row.finished_at = finished_at;
  if (result.abandoned) {
    row.status = RowStatus::kInterrupted;
    row.error = "interrupted while it ran (abandoned after the grace period)";
    return row;
  }
  if (!result.ok) {
    row.status = RowStatus::kError;
    row.error = printable_utf8(result.error);
    row.internal_error = result.internal_error;
    return row;
  }
  const ModelRecord& record = result.record;
  const double largest = record.input.largest_side;
  row.status = RowStatus::kOk;
  row.output = printable_utf8((output_dir / result.name).string());
  row.strips_3d = record.strips_3d;
  row.flat_strips = record.flat_strips;
  row.pages = record.pages;
  row.hausdorff_bound = record.hausdorff_bound;
  row.hausdorff_bound_percent = largest > 0 ? 100.0 * record.hausdorff_bound / largest : 0.0;
  row.certified = record.certified;
  return row;
}

nlohmann::json row_to_json(const BatchRow& row) {
  nlohmann::json json = {
      {"name", row.name}, {"input", row.input}, {"status", to_string(row.status)}};
  if (row.skipped) json["skipped"] = true;
  if (!row.error.empty()) json["error"] = row.error;
  if (row.status == RowStatus::kOk) {
    json["output"] = row.output;
    json["strips_3d"] = row.strips_3d;
    json["flat_strips"] = row.flat_strips;
    json["pages"] = row.pages;
    json["hausdorff_bound"] = row.hausdorff_bound;
    json["hausdorff_bound_percent"] = row.hausdorff_bound_percent;
    json["certified"] = row.certified;
  }
  if (row.started_at > 0) {
    json["work_seconds"] = row.work_seconds;
    json["wall_seconds"] = row.wall_seconds;
    json["queue_seconds"] = row.queue_seconds;
    json["started_at"] = row.started_at;
  }
  if (row.finished_at > 0) json["finished_at"] = row.finished_at;
  return json;
}

BatchRow row_from_json(const nlohmann::json& json) {
  BatchRow row;
  row.name = json.at("name").get<std::string>();
  row.input = json.value("input", std::string());
  row.status = row_status_from_string(json.at("status").get<std::string>());
  row.skipped = json.value("skipped", false);
  row.error = json.value("error", std::string());
  row.output = json.value("output", std::string());
  row.strips_3d = json.value("strips_3d", 0);
  row.flat_strips = json.value("flat_strips", 0);
  row.pages = json.value("pages", 0);
  row.hausdorff_bound = json.value("hausdorff_bound", 0.0);
  row.hausdorff_bound_percent = json.value("hausdorff_bound_percent", 0.0);
  row.certified = json.value("certified", false);
  row.work_seconds = json.value("work_seconds", 0.0);
  row.wall_seconds = json.value("wall_seconds", 0.0);
  row.queue_seconds = json.value("queue_seconds", 0.0);
  row.started_at = json.value("started_at", 0.0);
  row.finished_at = json.value("finished_at", 0.0);
  return row;
}

}  // namespace papercraft
