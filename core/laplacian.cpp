#include "core/laplacian.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>

namespace papercraft {

double clamped_cotangent(const OpenMesh::Vec3d& u, const OpenMesh::Vec3d& v, double limit) {
  const double cross = OpenMesh::cross(u, v).norm();
  const double dot = OpenMesh::dot(u, v);
  if (cross > 0.0) return std::clamp(dot / cross, -limit, limit);
  if (dot == 0.0) return 0.0;
  return dot > 0.0 ? limit : -limit;
}

std::vector<double> cotangent_edge_weights(const Mesh& mesh, double max_cotangent) {
  std::vector<double> weights(mesh.n_edges(), 0.0);
  for (auto f : mesh.faces()) {
    for (auto h : f.halfedges()) {
      const auto opposite = mesh.point(h.next().to());
      weights[h.edge().idx()] +=
          0.5 * clamped_cotangent(mesh.point(h.from()) - opposite, mesh.point(h.to()) - opposite,
                                  max_cotangent);
    }
  }
  return weights;
}

std::vector<double> floored_weights(const std::vector<double>& weights) {
  double sum = 0.0;
  int count = 0;
  for (double w : weights) {
    if (w > 0.0) {
      sum += w;
      ++count;
    }
  }
  const double floor = 1e-6 * (count > 0 ? sum / count : 1.0);
  std::vector<double> floored(weights.size());
  for (std::size_t i = 0; i < weights.size(); ++i) floored[i] = std::max(weights[i], floor);
  return floored;
}

DirichletSystem assemble_dirichlet(const std::vector<WeightedEdge>& edges,
                                   const std::vector<int>& free_index,
                                   const Eigen::VectorXd& values) {
  const int n_free = static_cast<int>(
      std::count_if(free_index.begin(), free_index.end(), [](int i) { return i >= 0; }));
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(4 * edges.size());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_free);
  for (const WeightedEdge& e : edges) {
    const double w = e.weight;
    const int ia = free_index[e.a];
    const int ib = free_index[e.b];
    if (ia >= 0) triplets.emplace_back(ia, ia, w);
    if (ib >= 0) triplets.emplace_back(ib, ib, w);
    if (ia >= 0 && ib >= 0) {
      triplets.emplace_back(ia, ib, -w);
      triplets.emplace_back(ib, ia, -w);
    } else if (ia >= 0) {
      rhs[ia] += w * values[e.b];
    } else if (ib >= 0) {
      rhs[ib] += w * values[e.a];
    }
  }
  DirichletSystem system;
  system.matrix.resize(n_free, n_free);
  system.matrix.setFromTriplets(triplets.begin(), triplets.end());
  system.rhs = std::move(rhs);
  return system;
}

std::optional<Eigen::VectorXd> solve_dirichlet(const DirichletSystem& system, bool lu) {
  Eigen::VectorXd x;
  if (lu) {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
    solver.compute(system.matrix);
    if (solver.info() != Eigen::Success) return std::nullopt;
    x = solver.solve(system.rhs);
    if (solver.info() != Eigen::Success) return std::nullopt;
  } else {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system.matrix);
    if (solver.info() != Eigen::Success) return std::nullopt;
    // LDLT also factors indefinite matrices; a non-positive pivot means the weights are broken.
    if (solver.vectorD().size() > 0 && solver.vectorD().minCoeff() <= 0.0) return std::nullopt;
    x = solver.solve(system.rhs);
    if (solver.info() != Eigen::Success) return std::nullopt;
  }
  if (!x.allFinite()) return std::nullopt;
  return x;
}

}  // namespace papercraft
