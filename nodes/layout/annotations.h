#pragma once
// What is printed on a piece besides its outline: seam labels, the piece number, fold lines
// and alignment marks where seams meet.

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/pattern.h"
#include "nodes/layout/layout_types.h"
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

/// The labels and number arrange_labels gave each piece it saw, by everything they depend on
/// (for one LayoutOptions; the piece's name by its length only).
class LabelCache {
 public:
  struct Entry {
    std::string name;  // the piece's name then (the key has its length only)
    std::vector<PieceLabel> labels;
    std::vector<std::size_t> kept;  // the position of each of `labels` among those given
    std::optional<PieceLabel> number;
    std::vector<std::string> warnings;
  };
  std::unordered_map<std::string, Entry> entries;
};

/// Sets the piece number (shrunk, not below min_text_mm, until it lies clear) and moves each
/// seam label along its chain (and shrinks it, down to min_text_mm) until its text box lies
/// on the piece, crosses no cut line (of the piece or its tabs) and is clear of the number
/// and the labels placed before it; else onto the seam's tab on this piece; else beside the
/// seam off the piece; else farther around the seam's middle, joined to it by a leader line
/// (PieceLabel::leader); a label that finds no such spot keeps its first one and is named in
/// `warnings`.
///
/// Where one pass leaves labels (or the number) with no clear spot, it tries again with those
/// placed first, and with the number after the labels, and keeps the pass that leaves fewest.
///
/// With a `cache`, a piece arranged before with the same options (the same triangles, corners,
/// loops, tabs, labels, chains and box) gets that result back, warnings included: a layout
/// tried several ways arranges each piece once.
void arrange_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                    const OrientedBox& box, const LayoutOptions& options,
                    std::vector<std::string>& warnings, LabelCache* cache = nullptr);

/// Half the width of a label's leader line as the layout keeps it clear (mm).
inline constexpr double kLeaderHalfWidth = 0.15;

/// The thin box a straight leader line (its first and last points) takes.
std::array<Vec2, 4> leader_box(const std::vector<Vec2>& leader);

/// The thin boxes a leader line (a polyline: straight, or bent round a corner) takes, one per
/// segment, for clearance checks and nesting.
std::vector<std::array<Vec2, 4>> leader_boxes(const std::vector<Vec2>& leader);

/// The boxes of the piece's number and seam labels (strip frame mm).
std::vector<std::array<Vec2, 4>> text_boxes(const Piece& piece);

/// The fold lines with the parts inside any of `boxes` cut out: no line crosses a label.
std::vector<FoldLine> clear_of_text(const std::vector<FoldLine>& folds,
                                    const std::vector<std::array<Vec2, 4>>& boxes);

}  // namespace papercraft::layout_internal
