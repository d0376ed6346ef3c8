#pragma once
// Seam resolution over all flat strips of one model: which boundary edges are glued to
// which, with matching labels (DESIGN.md section 4, strips.json boundary kinds).

#include <vector>

#include "core/strip.h"

namespace papercraft {

struct SeamOptions {
  /// Also glue an edge to several collinear edges that together cover it (a neighbour
  /// whose polyline has extra vertices on that edge).
  bool match_collinear = true;
  /// For collinear matching: how far an endpoint may lie off the other edge's line, and
  /// the smallest overlap that counts, relative to the longer edge's length.
  double collinear_tolerance = 1e-9;
};

/// Resolves every boundary edge of `strips` to Seam or Open, in place.
///
/// Two edges are glued when their 3D endpoints are the same points (compared exactly:
/// neighbouring strips share bit-identical cut polylines, and the two sides of a strip's
/// own cut are copies of the same vertices); an edge glued to edges of its own strip (an
/// opened ruling) is a seam with itself. Among several candidates an edge is paired with
/// the first, in strip and boundary order, traversing it the opposite way, then the same
/// way; a leftover third edge is glued to the first other one. With match_collinear an
/// edge still unmatched is glued to unmatched collinear edges covering all of it.
/// Unmatched edges become Open (an input boundary).
///
/// Seam edges get neighbour_strip (the id of the strip across, the one covering most of
/// the edge when several do) and a label "A1", "A2", ... numbered in strip and boundary
/// order. One label names one shared boundary: the edges glued to each other and every
/// run of consecutive seam edges of a strip whose partners are also consecutive (they
/// share a vertex at the same 3D point) carry the same label, on both sides.
/// Previous kinds, neighbours and labels are overwritten.
///
/// \pre boundary vertex indices are in range of vertices3d.
/// \throws InvalidInputException if a precondition fails.
/// Known limit: collinear matching only pairs edges the exact matching left unpaired, and
/// an edge only partly covered stays Open.
void label_seams(std::vector<FlatStrip>& strips, const SeamOptions& options = {});

}  // namespace papercraft
