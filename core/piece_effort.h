#pragma once
// What a few flat pieces cost a person to cut and glue, estimated before any layout: the
// assembly-effort terms (core/effort.h) of the pieces and of every seam with a side on one of
// them. The merge compares two states of the same stretch of surface with it (a piece and its
// neighbour apart, or hinged into one) and keeps the cheaper: a hinge that opens a slit too thin
// for a glue flap pays for the joining strip the layout will print there, and for the sawtooth
// corners of the slit's outline.
//
//   PieceEffortOptions options{.mm_per_unit = 200.0};
//   label_seams(local);                                     // the pieces and their neighbours
//   double cost = local_effort(local, {0, 1}, options);    // pieces 0 and 1, and their seams

#include <vector>

#include "core/effort.h"
#include "core/overlap_2d.h"
#include "core/strip.h"

namespace papercraft {

struct PieceEffortOptions {
  double mm_per_unit = 1.0;    // the print scale: model units to page mm
  double min_area_mm2 = 0.0;   // a piece under this counts as small (0: not counted)
  double flap_height_mm = 1.0;  // the lowest glue flap the layout prints
  EffortWeights weights{};
};

/// Whether a glue flap `height` mm high fits beside a seam side: `side` the side's points in page
/// mm, in order along the piece's boundary (the piece on the left, so the flap on the right), and
/// `piece` the piece's own triangles in page mm. As the layout plans flaps: the side is cut into
/// runs at turns over 15 degrees (or 30 in all), and a run has room where a trapezoid `height`
/// high on its chord, its ends at 75 degrees, pushed out past the run's bulge, overlaps no triangle
/// (a run of one edge at least 4 flap heights long also tries its halves and quarters). True when
/// any run has room.
bool flap_fits(const std::vector<Vec2>& side, TriangleGrid2& piece, double height);

/// The effort terms of strips[set] (indices) and of the seams with a side on one of them, after
/// label_seams ran on `strips` (which must hold every strip sharing an edge with the set; the
/// seams among the others are not counted). Pieces: one per strip of the set (page splits are
/// not foreseen). Seams: one per labelled chain with a side on the set; a chain with room for a
/// flap on neither side (flap_fits) counts a joining strip too. Sawtooth corners: on the set's
/// outlines. Small pieces: under min_area_mm2. Narrowness is not estimated (the merge checks it
/// where a join can change it).
/// \pre strip ids are distinct, boundary vertex indices in range. \throws InvalidInputException
///      on two strips with one id.
EffortTerms local_effort_terms(const std::vector<FlatStrip>& strips, const std::vector<int>& set,
                               const PieceEffortOptions& options);

/// effort_total of local_effort_terms.
double local_effort(const std::vector<FlatStrip>& strips, const std::vector<int>& set,
                    const PieceEffortOptions& options);

}  // namespace papercraft
