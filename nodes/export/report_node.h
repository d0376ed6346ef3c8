#pragma once
// report.json of one model (DESIGN.md section 4), shared by export.files and the runner.

#include <nlohmann/json.hpp>

#include "graph/messages.h"
#include "graph/model_run.h"

namespace papercraft {

/// The report of `model`, from its record (a failed model has only what it reached).
nlohmann::json model_report(const ModelRun& model);

}  // namespace papercraft
