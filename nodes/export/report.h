#pragma once
// report.json of one model (DESIGN.md section 4), shared by export.files and the runner.

#include <nlohmann/json.hpp>

#include "graph/messages.h"
#include "graph/model_run.h"

namespace papercraft {

/// The report of `model`; `strips` may be null (then input facts come from nowhere).
nlohmann::json model_report(const ModelRun& model, const ModelStrips* strips);

}  // namespace papercraft
