#pragma once

#include <vector>

#include "core/mesh.h"

namespace papercraft {

/// Gives every vertex of `mesh` the property kInputVertexProperty = its own index.
void tag_input_vertices(Mesh& mesh);

/// The trivial segmentation: the whole model is one part per connected component.
/// Parts carry kInputVertexProperty. \pre `mesh` is a valid triangle mesh.
std::vector<Mesh> segment_none(const Mesh& mesh);

}  // namespace papercraft
