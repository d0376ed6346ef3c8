#pragma once
// Shared by the segment node adapters: one Part message per segment.

#include <memory>
#include <vector>

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/node.h"

namespace papercraft {

inline void emit_parts(const Envelope& in, Emitter& out, std::vector<Mesh> parts) {
  auto model = in.get_shared<Model>();
  in.model->set_result("segments", static_cast<double>(parts.size()));
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Part part;
    part.mesh = std::make_shared<const Mesh>(std::move(parts[i]));
    part.path = std::to_string(i);
    part.model = model;
    out.emit(0, std::move(part));
  }
}

}  // namespace papercraft
