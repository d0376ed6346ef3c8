#include "nodes/segment/labelled_surface.h"

namespace papercraft {

LabelledSoup labelled_surface(const Mesh& mesh, const std::vector<int>& face_labels) {
  LabelledSoup surface = soup_of_vertices(mesh);
  if (surface.input_vertex.empty()) {
    for (auto v : mesh.vertices()) surface.input_vertex.push_back(v.idx());
  }
  for (auto f : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (auto v : f.vertices()) t[k++] = v.idx();
    surface.triangles.push_back(t);
    surface.origin_face.push_back(f.idx());
    surface.labels.push_back(face_labels[f.idx()]);
  }
  return surface;
}

}  // namespace papercraft
