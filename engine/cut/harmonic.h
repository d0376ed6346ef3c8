#pragma once
// The cut of a rejected part (the `cut` stage): a harmonic field between the two boundaries of
// a part and a cut of the part along one of its iso-lines (Massarwi, Gotsman, Elber 2007,
// section 3.2.2 "Splitting the mesh"; cotangent weights of Pinkall and Polthier 1993 / Meyer
// et al. 2003).
//
// Typical use by the cut node:
//   Eigen::VectorXd f = harmonic_field(part, boundary_a, boundary_b);
//   double value = field_value_at(part, f, witness);   // or hole_split_value(f, hole_loop)
//   std::vector<Mesh> pieces = cut_along_isoline(part, f, value);
//   if (pieces.size() == 1) { /* no progress: the iso-line separates nothing */ }

#include <Eigen/Core>
#include <vector>

#include "core/mesh.h"

namespace papercraft {

struct HarmonicOptions {
  /// Cotangents are clamped to [-max_cotangent, max_cotangent] so that nearly degenerate
  /// triangles cannot make the system infinite.
  double max_cotangent = 1e5;
  /// Solve with non-negative edge weights only (each weight raised to a tiny positive floor):
  /// the discrete maximum principle then holds exactly, but linear precision on obtuse
  /// triangles is lost. Also used automatically when the exact cotangent system fails.
  bool clamp_negative_weights = false;
  /// A connected component without any Dirichlet vertex is an error (TopologyException)
  /// unless this is set; then all its vertices get `unconstrained_value`.
  bool allow_unconstrained_components = false;
  double unconstrained_value = 0.0;
};

/// Harmonic field f on the vertices of `part`: the cotangent-weight Laplace equation
/// sum_j w_ij (f_i - f_j) = 0 at every free vertex, with f = 0 on `zero_vertices` and f = 1 on
/// `one_vertices` (natural Neumann condition on the other boundary vertices). Solved with
/// SimplicialLDLT on the reduced SPD system; if that fails, again with clamped non-negative
/// weights (LDLT, then SparseLU). Values are clamped to [0, 1].
/// A component with only 0-vertices (only 1-vertices) gets the constant 0 (1).
/// \return #V vector indexed by vertex index.
/// \pre part has no deleted elements (garbage_collection() done).
/// \throws InvalidInputException if either vertex list is empty, an index is out of range,
///   a vertex is in both lists, or part has deleted elements.
/// \throws TopologyException if a connected component has no Dirichlet vertex (see options).
/// \throws SolverException if no factorisation succeeds.
Eigen::VectorXd harmonic_field(const Mesh& part, const std::vector<int>& zero_vertices,
                               const std::vector<int>& one_vertices,
                               const HarmonicOptions& options = {});

/// Value of the piecewise-linear field f (#V) at the point of `part` closest to `point`
/// (brute force over the faces; parts are small).
/// \throws InvalidInputException if part has no faces or f.size() != #V.
double field_value_at(const Mesh& part, const Eigen::VectorXd& f, const Vec3& point);

/// The iso-value through a hole: the midpoint of min and max of f over the hole's boundary
/// loop (vertex indices), so the iso-line enters and leaves the hole and the cut splits it off.
/// \throws InvalidInputException if the loop is empty or an index is out of range of f.
double hole_split_value(const Eigen::VectorXd& f, const std::vector<int>& loop);

struct CutOptions {
  /// An edge crossing closer than this fraction of the edge to one of its vertices snaps to
  /// that vertex (which then counts as lying exactly on the iso-line). Valid range [0, 0.5);
  /// a fraction of at least 1e-12 is always used so that no zero-length edge is created.
  double snap_fraction = 0.05;
  /// A crossing closer than this distance (model units) to a vertex snaps too, whatever the
  /// edge's length: repeated cuts near one vertex would otherwise leave ever shorter edges
  /// and triangles far below the tolerance (and below what rounding can orient). 0: off.
  double snap_distance = 0.0;
  /// Passes that slide each crossing along its edge to the point that makes the cut shortest
  /// between its two neighbours on the line (the line stays on the surface, one straight
  /// segment per face): the exact iso-line zig-zags across long thin triangles (a coarsely
  /// triangulated flat region), and a zig-zag cut prints as a sawtooth edge nobody can cut or
  /// glue cleanly. Ends of the line (a crossing beside a vertex on the iso-line, or at the
  /// part's boundary) stay; a line without two ends apart (a closed loop, or a loop from a
  /// vertex on the iso-line back to it) is not straightened, as it would shrink. 0: the exact
  /// iso-line.
  int straighten_passes = 8;
  /// Only a crossing where the line turns by more than this (degrees, the two faces beside
  /// its edge unfolded into one plane) slides: a zig-zag turns sharply at every crossing, a
  /// smooth iso-line hardly at any, and stays where the field puts it. 0: every crossing.
  double straighten_turn_degrees = 30.0;
};

/// Cuts `part` along the iso-line f = value: each crossed edge gets one new vertex (position,
/// texture coordinates and f interpolated linearly; computed once, so neighbouring pieces
/// share bit-identical cut vertices), crossed triangles are split in 2 or 3, and the faces
/// with f < value and those with f > value are separated into connected components (through
/// edges). A vertex where one piece would touch itself (a pinch on the iso-line) is
/// duplicated, so every piece is a 2-manifold with compact indices.
/// Pieces with f < value come first; within a side, ordered by their lowest input face.
/// Texture coordinates and the int vertex property "v:input_vertex" are carried over when the
/// part has them (new vertices get -1).
/// If value is not strictly inside the range of f, or all faces end up on one side, the
/// result is {part} unchanged; a part of several components is then not split either.
/// \pre part has no deleted elements.
/// \throws InvalidInputException if f.size() != #V, f or value is not finite,
///   snap_fraction is outside [0, 0.5) or snap_distance is negative or not finite.
std::vector<Mesh> cut_along_isoline(const Mesh& part, const Eigen::VectorXd& f, double value,
                                    const CutOptions& options = {});

}  // namespace papercraft
