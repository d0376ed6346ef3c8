#pragma once

#include <vector>

#include "core/mesh.h"

namespace papercraft {

/// Name of the int vertex property mapping a part's vertex to its input vertex (-1: made
/// by a cut).
inline constexpr const char* kInputVertexProperty = "v:input_vertex";

/// Gives every vertex of `mesh` the property kInputVertexProperty = its own index.
void tag_input_vertices(Mesh& mesh);

/// The trivial segmentation: the whole model is one part per connected component.
/// Parts carry kInputVertexProperty. \pre `mesh` is a valid triangle mesh.
std::vector<Mesh> segment_none(const Mesh& mesh);

}  // namespace papercraft
