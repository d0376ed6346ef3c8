#pragma once
// Shared by the segment node adapters: one Part message per segment.

#include <memory>
#include <vector>

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/node.h"
#include "nodes/segment/parts_ply.h"

namespace papercraft {

/// Emits the parts; with `write_parts_ply`, first writes them coloured to <output>/parts.ply.
inline void emit_parts(const Envelope& in, Emitter& out, std::vector<Mesh> parts,
                       bool write_parts_ply = false) {
  auto model = in.get_shared<Model>();
  if (write_parts_ply) in.model->write_file("parts.ply", parts_ply(parts));
  const int count = static_cast<int>(parts.size());
  in.model->update([count](ModelRecord& record) { record.segments = count; });
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Part part;
    part.mesh = std::make_shared<const Mesh>(std::move(parts[i]));
    part.path = std::to_string(i);
    part.model = model;
    out.emit("out", std::move(part));
  }
}

}  // namespace papercraft
