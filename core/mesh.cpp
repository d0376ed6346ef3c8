#include "core/mesh.h"

#include <algorithm>
#include <string>

#include "core/errors.h"

namespace papercraft {

TriangleMesh to_triangle_mesh(const Mesh& mesh) {
  TriangleMesh out;
  out.vertices.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) out.vertices.push_back(to_eigen(mesh.point(v)));
  out.triangles.reserve(mesh.n_faces());
  for (auto f : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (auto v : f.vertices()) t[k++] = v.idx();
    out.triangles.push_back(t);
  }
  return out;
}

Mesh to_mesh(const TriangleMesh& input) {
  Mesh mesh;
  std::vector<Mesh::VertexHandle> handles;
  handles.reserve(input.vertices.size());
  for (const Vec3& p : input.vertices) handles.push_back(mesh.add_vertex(to_openmesh(p)));
  for (std::size_t i = 0; i < input.triangles.size(); ++i) {
    const Triangle& t = input.triangles[i];
    auto f = mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    if (!f.is_valid()) {
      throw TopologyException("triangle " + std::to_string(i) + " (vertices " +
                              std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                              std::to_string(t[2]) + ") makes the mesh non-manifold");
    }
  }
  return mesh;
}

std::vector<std::vector<int>> boundary_loops(const Mesh& mesh) {
  std::vector<char> seen(mesh.n_halfedges(), 0);
  std::vector<std::vector<int>> loops;
  std::vector<double> lengths;
  for (auto h : mesh.halfedges()) {
    if (!h.is_boundary() || seen[h.idx()] || mesh.status(h).deleted()) continue;
    std::vector<int> loop;
    double length = 0.0;
    auto cur = h;
    do {
      seen[cur.idx()] = 1;
      loop.push_back(cur.from().idx());
      length += mesh.calc_edge_length(cur);
      cur = cur.next();
    } while (cur != h && !seen[cur.idx()]);
    loops.push_back(std::move(loop));
    lengths.push_back(length);
  }
  std::vector<std::size_t> order(loops.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return lengths[a] > lengths[b]; });
  std::vector<std::vector<int>> sorted;
  for (std::size_t i : order) sorted.push_back(std::move(loops[i]));
  return sorted;
}

void require_no_deleted_elements(const Mesh& mesh, const char* function) {
  auto deleted = [&](auto range) {
    for (auto h : range)
      if (mesh.status(h).deleted()) return true;
    return false;
  };
  if (deleted(mesh.all_vertices()) || deleted(mesh.all_edges()) || deleted(mesh.all_faces())) {
    throw InvalidInputException(std::string(function) +
                                ": mesh has deleted elements; call garbage_collection() first");
  }
}

int euler_characteristic(const Mesh& mesh) {
  return static_cast<int>(mesh.n_vertices()) - static_cast<int>(mesh.n_edges()) +
         static_cast<int>(mesh.n_faces());
}

int connected_components(const Mesh& mesh) {
  std::vector<int> component(mesh.n_vertices(), -1);
  int count = 0;
  std::vector<Mesh::VertexHandle> stack;
  for (auto v : mesh.vertices()) {
    if (component[v.idx()] >= 0) continue;
    component[v.idx()] = count;
    stack.push_back(v);
    while (!stack.empty()) {
      auto cur = stack.back();
      stack.pop_back();
      for (auto w : mesh.vv_range(cur)) {
        if (component[w.idx()] < 0) {
          component[w.idx()] = count;
          stack.push_back(w);
        }
      }
    }
    ++count;
  }
  return count;
}

double surface_area(const Mesh& mesh) {
  double area = 0.0;
  for (auto f : mesh.faces()) area += mesh.calc_face_area(f);
  return area;
}

}  // namespace papercraft
