#pragma once
// Internal to the segment stage: smooth boundaries between parts. A boundary found on the
// dual graph (a minimum cut) runs along mesh edges, a staircase wherever the triangulation
// does not follow it; replacing it by an iso-line of a harmonic field between the two sides
// (the field the cut stage uses, Massarwi et al. 2007 section 3.2.2) gives a curve that
// crosses triangles freely.

#include "nodes/segment/labelled_surface.h"

namespace papercraft {

struct StraightenOptions {
  /// Half-width of the band around each boundary that may be re-assigned (model units);
  /// <= 0 leaves the surface unchanged.
  double band_width = 0;
  /// As CutOptions::snap_fraction: a crossing this close to an edge's end uses that vertex.
  double snap_fraction = 0.05;
  /// A boundary along which the surface folds by at least this angle on average (degrees,
  /// either way) follows a crease and is kept as it is.
  double crease_degrees = 30;
};

/// For each pair of labels a < b whose triangles share an edge (in order of (a, b)): the
/// harmonic field f (cotangent weights, clamped non-negative so the maximum principle holds)
/// on the triangles of a and b, with f = 0 (1) on the vertices of a (b) farther than
/// band_width from the a-b boundary, and on every vertex that also touches a third part
/// (0.5 where it touches both a and b), so that no edge shared with a third part is ever split;
/// then the triangles are split along f = 0.5 and relabelled by side. Texture coordinates are
/// interpolated; new points get input_vertex -1. A pair whose boundary follows a crease (see
/// crease_degrees), whose re-assignment would disconnect a part or empty it, or whose field
/// cannot be solved keeps its boundary.
void straighten_boundaries(LabelledSoup& surface, const StraightenOptions& options);

}  // namespace papercraft
