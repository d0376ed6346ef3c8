#pragma once
// Seam resolution over all flat strips of one model: which boundary edge is glued to which,
// with one label per chain shared by two pieces (DESIGN.md section 4, strips.json seams).

#include <string>
#include <vector>

#include "core/strip.h"

namespace papercraft {

struct SeamOptions {
  /// A boundary vertex of one strip lies on a boundary edge of another (a T-junction) when
  /// it is within this fraction of the edge's length of the edge's segment, strictly
  /// between its ends.
  double t_junction_tolerance = 1e-9;
};

/// Splits boundary edges at the boundary vertices of other strips (or of the same strip)
/// that lie on them: where a part was cut after its neighbour had become a strip, the cut
/// added a vertex to their shared boundary on one side only. The edge's triangle is split
/// into a fan from its third vertex; each new vertex copies the other strip's 3D point bit
/// for bit and is placed in 2D (and in uv) along the flat edge at the same fraction of its
/// length, so the strip stays isometric. Only edges without an exact partner (the same two
/// 3D points the other way) are split, at the ends of other such edges. Returns the number of
/// vertices inserted. Boundary edges that are split keep their place in `boundary`, replaced
/// by their pieces in order.
/// \pre boundary vertex indices are in range; every boundary edge (v0, v1) is an edge of a
///   triangle of its strip (as flat_boundary makes them); otherwise that edge is not split.
/// \throws InvalidInputException if a vertex index is out of range.
int split_t_junctions(std::vector<FlatStrip>& strips, const SeamOptions& options = {});

/// Resolves every boundary edge of `strips` to Seam or Open, in place, after
/// split_t_junctions.
///
/// Two edges are glued when their 3D end points are the same points (compared exactly:
/// neighbouring strips share bit-identical cut polylines, the two sides of a strip's own
/// opened ruling are copies of the same vertices, and split_t_junctions inserted the missing
/// ones). Each edge has at most one partner: among edges with the same two end points, an
/// edge is paired with the first, in strip and boundary order, that runs the other way, then
/// with the first that runs the same way; an edge left over is Open, as is an edge on no
/// other strip's boundary (an input boundary).
///
/// Seam edges get neighbour_strip (the id of the strip across), partner_edge (its index in
/// that strip's boundary) and a label "A1", "A2", ... One label names one maximal chain of
/// consecutive seam edges of one strip glued to consecutive edges of one other strip (or of
/// itself: an opened ruling), and both sides carry it. Labels are numbered in strip and
/// boundary order. Previous kinds, neighbours and labels are overwritten.
///
/// \pre boundary vertex indices are in range of vertices3d.
/// \throws InvalidInputException if a precondition fails.
void label_seams(std::vector<FlatStrip>& strips, const SeamOptions& options = {});

/// One side of a labelled seam: a strip id and the indices of its boundary edges carrying
/// the label, in chain order (each edge's v1 is the next one's v0).
struct SeamSide {
  int strip = -1;
  std::vector<int> edges;
};

/// A labelled seam and its two sides (the same strip twice for an opened ruling), side 0
/// holding the label's first edge in strip and boundary order.
struct SeamChain {
  std::string label;
  SeamSide sides[2];
};

/// The chains label_seams made, in label order. \pre label_seams ran on `strips`.
std::vector<SeamChain> labelled_chains(const std::vector<FlatStrip>& strips);

}  // namespace papercraft
