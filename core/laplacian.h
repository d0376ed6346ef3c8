#pragma once
// The cotangent Laplacian and its Dirichlet problem (pmp-library's laplace_matrix, libigl's
// min_quad_with_fixed): the harmonic fields of the cut stage and of boundary straightening.
//
// With edge weights w_ij, a field x is harmonic at vertex i when sum_j w_ij (x_i - x_j) = 0.
// Fixing x on some vertices leaves the reduced system A y = b over the free ones, symmetric
// positive definite when every weight is positive and every free vertex is connected to a
// fixed one.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "core/mesh.h"

namespace papercraft {

/// cot of the angle between u and v, clamped to [-limit, limit]: parallel vectors give
/// +-limit, a zero vector 0.
double clamped_cotangent(const OpenMesh::Vec3d& u, const OpenMesh::Vec3d& v, double limit);

/// Meyer et al. 2003, eq. (8): w_ij = (cot alpha_ij + cot beta_ij) / 2 for every edge of
/// `mesh` (indexed by edge index; a boundary edge has one term), cotangents clamped to
/// max_cotangent. \pre no deleted elements.
std::vector<double> cotangent_edge_weights(const Mesh& mesh, double max_cotangent);

/// The weights raised to a floor of 1e-6 times their mean positive value (1e-6 if none is
/// positive): non-negative weights make the reduced system an M-matrix (the discrete maximum
/// principle holds), the floor keeps every edge connecting.
std::vector<double> floored_weights(const std::vector<double>& weights);

/// One weighted edge between vertices a and b.
struct WeightedEdge {
  int a = -1;
  int b = -1;
  double weight = 0.0;
};

/// The reduced system of a Dirichlet problem: rows are the free vertices.
struct DirichletSystem {
  Eigen::SparseMatrix<double> matrix;
  Eigen::VectorXd rhs;
};

/// Assembles A y = b over the vertices with free_index[v] >= 0 (numbered 0..n_free-1; the
/// others are fixed at values[v]). Entries are summed in the order of `edges`.
DirichletSystem assemble_dirichlet(const std::vector<WeightedEdge>& edges,
                                   const std::vector<int>& free_index,
                                   const Eigen::VectorXd& values);

/// Solves a Dirichlet system by sparse Cholesky (SimplicialLDLT, refusing a non-positive
/// pivot) or, with `lu`, by SparseLU. nullopt when the factorisation fails or the solution
/// is not finite.
std::optional<Eigen::VectorXd> solve_dirichlet(const DirichletSystem& system, bool lu = false);

}  // namespace papercraft
