#include "runner/resume.h"

#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "runner/sha256.h"

namespace papercraft {

namespace {

nlohmann::json key_json(const ResultKey& key) {
  return {{"config_sha256", key.config_sha256},
          {"tolerance", key.tolerance},
          {"paper",
           {{"height_mm", key.paper.height_mm},
            {"scale", key.paper.scale},
            {"min_width_mm", key.paper.min_width_mm},
            {"min_area_mm2", key.paper.min_area_mm2}}},
          {"version", key.version}};
}

}  // namespace

ResultKey result_key(const RunSettings& settings) {
  return {sha256_hex(settings.config_text), settings.tolerance.to_string(), settings.paper,
          PAPERCRAFT_VERSION};
}

void write_finished_record(const std::filesystem::path& model_dir, const BatchRow& row,
                           const ResultKey& key, const std::string& input_sha256) {
  nlohmann::json record = {{"key", key_json(key)}, {"row", row_to_json(row)}};
  record["key"]["input_sha256"] = input_sha256;
  write_file_atomic(model_dir / kFinishedRecord, record.dump(2) + "\n");
}

std::optional<BatchRow> earlier_result(const std::filesystem::path& model_dir,
                                       const std::filesystem::path& input, const ResultKey& key) {
  std::ifstream in(model_dir / kFinishedRecord, std::ios::binary);
  if (!in) return std::nullopt;
  try {
    std::ostringstream text;
    text << in.rdbuf();
    const nlohmann::json record = nlohmann::json::parse(text.str());
    nlohmann::json stored = record.at("key");
    const std::string input_sha256 = stored.at("input_sha256").get<std::string>();
    stored.erase("input_sha256");
    if (stored != key_json(key)) return std::nullopt;
    BatchRow row = row_from_json(record.at("row"));
    if (row.status != RowStatus::kOk) return std::nullopt;
    if (file_sha256_hex(input) != input_sha256) return std::nullopt;
    row.skipped = true;
    return row;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable or from another version of the format: run it again
  }
}

}  // namespace papercraft
