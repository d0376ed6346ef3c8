#pragma once
// What is printed on a piece besides its outline: seam labels, the piece number, fold lines
// and alignment marks where seams meet.

#include <string>
#include <vector>

#include "core/pattern.h"
#include "nodes/layout/pages.h"
#include "nodes/layout/pieces.h"
#include "nodes/layout/polygon_2d.h"
#include "nodes/layout/seam_pairing.h"

namespace papercraft::layout_internal {

/// Ticks of `length` across the cut line at the ends of `chain` where the boundary goes on
/// as another seam: the places where two seams meet, printed on both pieces.
void add_alignment_marks(const StripData& data, Piece& piece, const Chain& chain, double length);

/// The seam label of a chain: centred on the chain's arc-length midpoint, inside the piece,
/// along the edge there, smaller where the chain is short.
PieceLabel chain_label(const StripData& data, const Piece& piece, const Chain& chain,
                       const std::string& text, double size);

/// Fold lines (strip frame mm) of the piece's inner edges bent more than threshold_degrees;
/// those bent less than strong_degrees are gentle.
std::vector<FoldLine> piece_folds(const StripData& data, const Piece& piece,
                                  double threshold_degrees, double strong_degrees);

/// The piece number (Piece::name: 1..N, "12a", "12b" for a split strip) at the incentre of a
/// triangle with (nearly) the largest inscribed circle, the one nearest the piece's centroid,
/// sized to fit that circle and running along the box's long side.
PieceLabel piece_number(const StripData& data, const Piece& piece, const OrientedBox& box,
                        const LayoutOptions& options);

/// Sets the piece number and moves each seam label along its chain (and shrinks it, down to
/// 1.2 mm) until its text box lies on the piece and clear of the piece number and the labels
/// placed before it; a label that finds no such spot keeps its first one.
void arrange_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                    const OrientedBox& box, const LayoutOptions& options);

}  // namespace papercraft::layout_internal
