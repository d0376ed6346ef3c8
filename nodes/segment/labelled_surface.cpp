#include "nodes/segment/labelled_surface.h"

#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>

#include "core/errors.h"
#include "nodes/segment/none.h"

namespace papercraft {
namespace {

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void unite(std::vector<std::size_t>& parent, std::size_t a, std::size_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a == b) return;
  if (a < b) std::swap(a, b);
  parent[a] = b;
}

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace

LabelledSurface labelled_surface(const Mesh& mesh, const std::vector<int>& face_labels) {
  LabelledSurface surface;
  surface.points.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) surface.points.push_back(mesh.point(v));
  if (mesh.has_vertex_texcoords2D()) {
    for (auto v : mesh.vertices()) surface.texcoords.push_back(mesh.texcoord2D(v));
  }
  OpenMesh::VPropHandleT<int> input_vertex;
  const bool tagged = mesh.get_property_handle(input_vertex, kInputVertexProperty);
  for (auto v : mesh.vertices())
    surface.input_vertex.push_back(tagged ? mesh.property(input_vertex, v) : v.idx());
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

std::vector<Mesh> parts_of(const LabelledSurface& surface) {
  const std::size_t n = surface.triangles.size();
  std::unordered_map<std::uint64_t, std::vector<int>> edge_triangles;
  edge_triangles.reserve(3 * n);
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = surface.triangles[f];
    for (int k = 0; k < 3; ++k)
      edge_triangles[edge_key(t[k], t[(k + 1) % 3])].push_back(static_cast<int>(f));
  }
  // Parts: triangles of one label joined through edges. Fans: corners (triangle, vertex) of one
  // part joined through the edges at that vertex; each fan becomes its own output vertex.
  std::vector<std::size_t> part_parent(n);
  std::iota(part_parent.begin(), part_parent.end(), std::size_t{0});
  std::vector<std::size_t> fan_parent(3 * n);
  std::iota(fan_parent.begin(), fan_parent.end(), std::size_t{0});
  auto corner = [&](int triangle, int vertex) {
    const Triangle& t = surface.triangles[triangle];
    const int k = t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2);
    return static_cast<std::size_t>(3 * triangle + k);
  };
  // Visiting the edges in triangle order keeps the unions independent of hash order.
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = surface.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[k];
      const int b = t[(k + 1) % 3];
      for (int g : edge_triangles.at(edge_key(a, b))) {
        if (g <= static_cast<int>(f) || surface.labels[g] != surface.labels[f]) continue;
        unite(part_parent, f, g);
        unite(fan_parent, corner(static_cast<int>(f), a), corner(g, a));
        unite(fan_parent, corner(static_cast<int>(f), b), corner(g, b));
      }
    }
  }

  std::vector<int> part_of_root(n, -1);
  std::vector<std::vector<int>> part_triangles;
  std::vector<std::pair<int, int>> part_key;  // (label, lowest origin face)
  for (std::size_t f = 0; f < n; ++f) {
    const std::size_t root = find_root(part_parent, f);
    if (part_of_root[root] < 0) {
      part_of_root[root] = static_cast<int>(part_triangles.size());
      part_triangles.emplace_back();
      part_key.emplace_back(surface.labels[f], surface.origin_face[f]);
    }
    const int p = part_of_root[root];
    part_triangles[p].push_back(static_cast<int>(f));
    part_key[p].second = std::min(part_key[p].second, surface.origin_face[f]);
  }
  std::vector<std::size_t> order(part_triangles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return part_key[a] < part_key[b]; });

  const bool has_texcoords = !surface.texcoords.empty();
  std::vector<Mesh> parts;
  parts.reserve(order.size());
  std::unordered_map<std::size_t, Mesh::VertexHandle> vertex_of_fan;
  for (std::size_t p : order) {
    Mesh mesh;
    if (has_texcoords) mesh.request_vertex_texcoords2D();
    auto input_vertex =
        OpenMesh::getOrMakeProperty<OpenMesh::VertexHandle, int>(mesh, kInputVertexProperty);
    std::vector<std::pair<int, std::size_t>> used;  // (point, fan)
    for (int f : part_triangles[p])
      for (int v : surface.triangles[f]) used.emplace_back(v, find_root(fan_parent, corner(f, v)));
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    vertex_of_fan.clear();
    for (const auto& [v, fan] : used) {
      const auto handle = mesh.add_vertex(surface.points[v]);
      vertex_of_fan.emplace(fan, handle);
      if (has_texcoords) mesh.set_texcoord2D(handle, surface.texcoords[v]);
      input_vertex[handle] = surface.input_vertex[v];
    }
    for (int f : part_triangles[p]) {
      const Triangle& t = surface.triangles[f];
      Mesh::VertexHandle corners[3];
      for (int k = 0; k < 3; ++k)
        corners[k] = vertex_of_fan.at(find_root(fan_parent, corner(f, t[k])));
      if (!mesh.add_face(corners[0], corners[1], corners[2]).is_valid()) {
        throw TopologyException("segmentation: triangle " + std::to_string(f) + " (in face " +
                                std::to_string(surface.origin_face[f]) +
                                ") cannot be added to its part without a non-manifold edge");
      }
    }
    parts.push_back(std::move(mesh));
  }
  return parts;
}

}  // namespace papercraft
