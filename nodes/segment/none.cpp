#include "nodes/segment/none.h"

#include <OpenMesh/Core/Utils/PropertyManager.hh>

#include "core/labelled_soup.h"

namespace papercraft {

void tag_input_vertices(Mesh& mesh) {
  auto input_vertex =
      OpenMesh::getOrMakeProperty<OpenMesh::VertexHandle, int>(mesh, kInputVertexProperty);
  for (auto v : mesh.vertices()) input_vertex[v] = v.idx();
}

std::vector<Mesh> segment_none(const Mesh& mesh) {
  Mesh tagged = mesh;
  tag_input_vertices(tagged);
  if (connected_components(tagged) == 1) return {std::move(tagged)};
  return split_connected_components(tagged);
}

}  // namespace papercraft
