#pragma once
// Sequential isometric unfolding of a triangulated ruled strip: the `unfold` stage's
// algorithm (paper section 3.3; DESIGN.md "Unfold").
//
// Triangles are laid flat one after another across the edge they share with an already
// placed triangle, the third vertex placed from exact 3D lengths on the side that keeps
// the triangle counter-clockwise (never mirrored). A closed strip is first opened along
// its shortest ruling. Where the next triangle would overlap the flat strip being built
// (tested against a uniform grid of the placed triangles), a new flat strip starts there.
//
// Example (node config): unfold: {impl: unfold.sequential, to: [merge]}

#include <vector>

#include "core/strip.h"

namespace papercraft {

struct UnfoldOptions {
  /// Two triangles of one flat strip overlap when their interiors penetrate deeper than
  /// this times the strip's mean edge length; touching edges and vertices and rounding
  /// stay below it.
  double overlap_tolerance = 1e-9;
  /// A closed strip is opened along its shortest ruling; rulings within this relative
  /// length of the shortest count as equally short and the first in vertex order wins, so
  /// the choice is stable under rounding (a cylinder opens at A's first vertex).
  double ruling_tie_tolerance = 1e-9;
  /// A closed strip that unfolds into one piece whose opened ruling lands on itself (both
  /// copies within this times the mean edge length: the strip lies flat, as a cap does) is
  /// welded shut there: no slit is cut into a flat piece.
  double flat_close_tolerance = 1e-9;
};

/// Unfolds `strip` into one or more flat strips (several only where one would overlap
/// itself), with ids first_flat_id, first_flat_id + 1, ... in the order they are started
/// and source_strip = source_strip_id.
///
/// Each flat strip has its own vertex arrays: a 3D vertex appears once per flat strip and
/// once more on each side of a cut (the opened ruling, a split). vertices3d are the strip's
/// coordinates copied bit for bit, so label_seams can match cut edges. uvs are copied
/// when the strip has them. `boundary` holds every boundary edge, the strip on its left,
/// chained into loops, kind Cut (label_seams resolves seams and open edges).
///
/// Every placed triangle keeps its 3D edge lengths (to rounding) and, when it has area,
/// a positive signed area in 2D. Triangles are visited breadth-first over the dual graph
/// (edges shared by exactly two consistently oriented triangles), starting from a
/// triangle with at most one neighbour, so a ruled strip is laid out in order along its
/// rulings; any mesh is accepted, a remaining dual cycle being cut where the traversal
/// closes it. Zero-area triangles are placed on a line; one across a zero-length edge is
/// hinged straight on from its parent. A triangle repeating a vertex index is skipped; one
/// with two corners at the same 3D point (bit for bit; an apex on its own polyline) is dropped
/// from the result, and those corners welded into one vertex where they coincide on paper.
///
/// \pre a_count + b_count == #vertices (or both 0 for a general mesh, which is never
///      opened along a ruling); indices in range; uvs empty or one per vertex; finite
///      coordinates; options' tolerances >= 0.
/// \throws InvalidInputException if a precondition fails.
/// Where a strip must be split, it is split into the fewest overlap-free runs of
/// consecutive triangles, of similar area (no sliver left at the end of a split strip), when
/// its triangles form one path (every ruled strip); other meshes split where the overlap
/// first occurs.
/// Known limit: a non-manifold edge (three or more triangles) or an inconsistently oriented
/// pair is cut.
std::vector<FlatStrip> unfold_strip(const RuledStrip& strip, int source_strip_id, int first_flat_id,
                                    const UnfoldOptions& options = {});

}  // namespace papercraft
