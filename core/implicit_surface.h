#pragma once
// Closed surfaces from implicit functions, for the analytic test meshes (generate.h): the zero
// set of a sampled field polygonised by marching tetrahedra, then remeshed towards an even
// edge length on the true zero set.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

/// A field sampled at the nodes of a regular grid (values < 0 inside).
struct ImplicitGrid {
  Vec3 origin;
  double cell = 0.0;
  std::array<int, 3> nodes{};  // per axis
  std::vector<double> values;

  std::int64_t node_index(int x, int y, int z) const {
    return (static_cast<std::int64_t>(z) * nodes[1] + y) * nodes[0] + x;
  }
  Vec3 position(int x, int y, int z) const { return origin + cell * Vec3(x, y, z); }
};

/// Zero set of the piecewise-linear interpolant of grid.values over the Kuhn (Freudenthal)
/// tetrahedralisation; values < 0 are inside. The result is closed and manifold whenever no
/// value is 0 and the grid's outer nodes are all outside.
TriangleMesh marching_tetrahedra(const ImplicitGrid& grid);

/// The polygonised zero set `input` of `field` remeshed towards edge length target_length in
/// `rounds` rounds of collapses, flips and tangential relaxation projected back onto the zero
/// set (Botsch & Kobbelt 2004 without splits); the topology is kept (the link condition, Dey et
/// al. 1999) and no face turns more than 45 degrees from the field's gradient.
/// \pre input is a closed manifold polygonising the zero set of `field`.
TriangleMesh remesh_implicit_surface(const TriangleMesh& input,
                                     std::function<double(const Vec3&)> field, double target_length,
                                     int rounds);

}  // namespace papercraft
