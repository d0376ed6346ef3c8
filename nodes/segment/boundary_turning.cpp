#include "nodes/segment/boundary_turning.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace papercraft {
namespace {

using PointKey = std::array<double, 3>;

PointKey key_of(const OpenMesh::Vec3d& p) {
  return {p[0], p[1], p[2]};
}

}  // namespace

double boundary_turning_per_length(const std::vector<Mesh>& parts) {
  std::map<std::pair<PointKey, PointKey>, int> occurrences;
  for (const Mesh& part : parts) {
    for (auto h : part.halfedges()) {
      if (!h.is_boundary()) continue;
      PointKey a = key_of(part.point(h.from()));
      PointKey b = key_of(part.point(h.to()));
      if (b < a) std::swap(a, b);
      ++occurrences[{a, b}];
    }
  }
  std::map<PointKey, std::vector<PointKey>> neighbours;
  double length = 0;
  for (const auto& [edge, count] : occurrences) {
    if (count < 2) continue;
    neighbours[edge.first].push_back(edge.second);
    neighbours[edge.second].push_back(edge.first);
    const Vec3 a(edge.first[0], edge.first[1], edge.first[2]);
    const Vec3 b(edge.second[0], edge.second[1], edge.second[2]);
    length += (b - a).norm();
  }
  if (!(length > 0)) return 0.0;
  double turning = 0;
  for (const auto& [point, adjacent] : neighbours) {
    if (adjacent.size() != 2) continue;
    const Vec3 p(point[0], point[1], point[2]);
    const Vec3 in = p - Vec3(adjacent[0][0], adjacent[0][1], adjacent[0][2]);
    const Vec3 out = Vec3(adjacent[1][0], adjacent[1][1], adjacent[1][2]) - p;
    const double norms = in.norm() * out.norm();
    if (norms > 0) turning += std::acos(std::clamp(in.dot(out) / norms, -1.0, 1.0));
  }
  return turning / length;
}

}  // namespace papercraft
