#include "core/labelled_soup.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>

#include "core/edge_map.h"
#include "core/errors.h"
#include "core/union_find.h"

namespace papercraft {

LabelledSoup soup_of_vertices(const Mesh& mesh) {
  LabelledSoup soup;
  soup.points.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) soup.points.push_back(mesh.point(v));
  if (mesh.has_vertex_texcoords2D()) {
    for (auto v : mesh.vertices()) soup.texcoords.push_back(mesh.texcoord2D(v));
  }
  OpenMesh::VPropHandleT<int> input_vertex;
  if (mesh.get_property_handle(input_vertex, kInputVertexProperty)) {
    for (auto v : mesh.vertices()) soup.input_vertex.push_back(mesh.property(input_vertex, v));
  }
  return soup;
}

std::vector<Mesh> build_pieces(const LabelledSoup& soup) {
  const std::size_t n = soup.triangles.size();
  const EdgeTriangles around = edge_triangles(soup.triangles);
  // Pieces: triangles of one label joined through edges. Fans: corners (triangle, vertex) of
  // one piece joined through the edges at that vertex; each fan becomes its own vertex.
  UnionFind pieces(n);
  UnionFind fans(3 * n);
  auto corner = [&](int triangle, int vertex) {
    const Triangle& t = soup.triangles[triangle];
    const int k = t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2);
    return static_cast<std::size_t>(3 * triangle + k);
  };
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[k];
      const int b = t[(k + 1) % 3];
      for (int g : around.at(undirected_edge_key(a, b))) {
        if (g <= static_cast<int>(f) || soup.labels[g] != soup.labels[f]) continue;
        pieces.unite(f, g);
        fans.unite(corner(static_cast<int>(f), a), corner(g, a));
        fans.unite(corner(static_cast<int>(f), b), corner(g, b));
      }
    }
  }

  std::vector<int> piece_of_root(n, -1);
  std::vector<std::vector<int>> piece_triangles;
  std::vector<std::pair<int, int>> piece_key;  // (label, lowest origin face)
  for (std::size_t f = 0; f < n; ++f) {
    const std::size_t root = pieces.find(f);
    if (piece_of_root[root] < 0) {
      piece_of_root[root] = static_cast<int>(piece_triangles.size());
      piece_triangles.emplace_back();
      piece_key.emplace_back(soup.labels[f], soup.origin_face[f]);
    }
    const int p = piece_of_root[root];
    piece_triangles[p].push_back(static_cast<int>(f));
    piece_key[p].second = std::min(piece_key[p].second, soup.origin_face[f]);
  }
  std::vector<std::size_t> order(piece_triangles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return piece_key[a] < piece_key[b]; });

  const bool has_texcoords = !soup.texcoords.empty();
  const bool has_input_vertex = !soup.input_vertex.empty();
  std::vector<Mesh> result;
  result.reserve(order.size());
  std::unordered_map<std::size_t, Mesh::VertexHandle> vertex_of_fan;
  for (std::size_t p : order) {
    Mesh mesh;
    if (has_texcoords) mesh.request_vertex_texcoords2D();
    OpenMesh::VPropHandleT<int> input_vertex;
    if (has_input_vertex) mesh.add_property(input_vertex, kInputVertexProperty);
    std::vector<std::pair<int, std::size_t>> used;  // (soup point, fan)
    for (int f : piece_triangles[p])
      for (int v : soup.triangles[f]) used.emplace_back(v, fans.find(corner(f, v)));
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    vertex_of_fan.clear();
    for (const auto& [v, fan] : used) {
      const auto handle = mesh.add_vertex(soup.points[v]);
      vertex_of_fan.emplace(fan, handle);
      if (has_texcoords) mesh.set_texcoord2D(handle, soup.texcoords[v]);
      if (has_input_vertex) mesh.property(input_vertex, handle) = soup.input_vertex[v];
    }
    for (int f : piece_triangles[p]) {
      const Triangle& t = soup.triangles[f];
      Mesh::VertexHandle corners[3];
      for (int k = 0; k < 3; ++k) corners[k] = vertex_of_fan.at(fans.find(corner(f, t[k])));
      if (!mesh.add_face(corners[0], corners[1], corners[2]).is_valid()) {
        throw TopologyException("triangle " + std::to_string(f) + " (vertices " +
                                std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                                std::to_string(t[2]) + ", in face " +
                                std::to_string(soup.origin_face[f]) +
                                ") cannot be added to its piece without a non-manifold edge");
      }
    }
    result.push_back(std::move(mesh));
  }
  return result;
}

std::vector<Mesh> split_connected_components(const Mesh& mesh) {
  require_no_deleted_elements(mesh, "split_connected_components");
  LabelledSoup soup = soup_of_vertices(mesh);
  soup.triangles.reserve(mesh.n_faces());
  for (auto face : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (auto v : face.vertices()) t[k++] = v.idx();
    soup.triangles.push_back(t);
    soup.origin_face.push_back(face.idx());
  }
  soup.labels.assign(soup.triangles.size(), 0);
  return build_pieces(soup);
}

}  // namespace papercraft
