#include "engine/refine/rejoin.h"

#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <array>
#include <map>
#include <vector>

namespace papercraft {

std::optional<Mesh> glue_pieces(const Mesh& a, const Mesh& b) {
  using Key = std::array<double, 3>;
  const auto key = [](const OpenMesh::Vec3d& p) { return Key{p[0], p[1], p[2]}; };
  std::map<Key, int> boundary_of_a;
  for (auto v : a.vertices())
    if (a.is_boundary(v)) boundary_of_a.emplace(key(a.point(v)), v.idx());
  Mesh glued;
  const bool uvs = a.has_vertex_texcoords2D() && b.has_vertex_texcoords2D();
  if (uvs) glued.request_vertex_texcoords2D();
  auto input =
      OpenMesh::getOrMakeProperty<OpenMesh::VertexHandle, int>(glued, kInputVertexProperty);
  OpenMesh::VPropHandleT<int> handle_a, handle_b;
  const bool has_a = a.get_property_handle(handle_a, kInputVertexProperty);
  const bool has_b = b.get_property_handle(handle_b, kInputVertexProperty);
  std::vector<Mesh::VertexHandle> of_a, of_b;
  for (auto v : a.vertices()) {
    const auto g = glued.add_vertex(a.point(v));
    input[g] = has_a ? a.property(handle_a, v) : -1;
    if (uvs) glued.set_texcoord2D(g, a.texcoord2D(v));
    of_a.push_back(g);
  }
  std::size_t shared = 0;
  for (auto v : b.vertices()) {
    if (b.is_boundary(v)) {
      const auto it = boundary_of_a.find(key(b.point(v)));
      if (it != boundary_of_a.end()) {
        of_b.push_back(of_a[it->second]);
        ++shared;
        continue;
      }
    }
    const auto g = glued.add_vertex(b.point(v));
    input[g] = has_b ? b.property(handle_b, v) : -1;
    if (uvs) glued.set_texcoord2D(g, b.texcoord2D(v));
    of_b.push_back(g);
  }
  if (shared < 2) return std::nullopt;
  for (auto f : a.faces()) {
    std::vector<Mesh::VertexHandle> corners;
    for (auto v : f.vertices()) corners.push_back(of_a[v.idx()]);
    if (!glued.add_face(corners).is_valid()) return std::nullopt;
  }
  for (auto f : b.faces()) {
    std::vector<Mesh::VertexHandle> corners;
    for (auto v : f.vertices()) corners.push_back(of_b[v.idx()]);
    if (!glued.add_face(corners).is_valid()) return std::nullopt;
  }
  // They must share an edge, not only points.
  std::size_t inner_before = 0, inner_after = 0;
  for (auto e : a.edges()) inner_before += !a.is_boundary(e);
  for (auto e : b.edges()) inner_before += !b.is_boundary(e);
  for (auto e : glued.edges()) inner_after += !glued.is_boundary(e);
  if (inner_after == inner_before) return std::nullopt;
  for (auto v : glued.vertices())
    if (!glued.is_manifold(v)) return std::nullopt;
  return glued;
}

}  // namespace papercraft
