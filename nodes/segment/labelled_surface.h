#pragma once
// Internal to the segment stage: the whole model as one labelled triangle soup
// (core/labelled_soup.h), each triangle labelled with its part. Boundaries are refined on this
// one surface and the parts cut out only at the end (build_pieces).

#include <vector>

#include "core/labelled_soup.h"

namespace papercraft {

/// The model's faces with the given labels (#F), origin_face the face index. input_vertex is
/// the model's "v:input_vertex" property where it has one, else the vertex index.
/// \pre no deleted elements.
LabelledSoup labelled_surface(const Mesh& mesh, const std::vector<int>& face_labels);

}  // namespace papercraft
