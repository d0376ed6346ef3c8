#pragma once
// The order in which to glue the printed pieces: a greedy growth over the piece graph of a
// pattern layout (pieces as nodes, seams as edges weighted by their length on paper).
//
// Each connected part of the model starts from a large central piece: among its pieces with
// at least `large_share` of the area of its largest, the one with the fewest seams between it
// and all the others (summed over them, counted in pieces crossed), then the larger, then the
// lower number. Then, one step at a time, the piece that shares the most seam length with what
// is built joins it (ties: the lower number), glued first to the built piece it shares the
// most with; its other seams to built pieces close loops of the model and are glued after it,
// as are the seams of a piece with itself (a cone or a tube closed along a ruling). So every
// step's model is one connected shell, and a part that closes on itself closes last. Separate
// parts follow each other, the larger (by area) first, each its own sequence.

#include <string>
#include <vector>

#include "core/pattern.h"

namespace papercraft {

struct BuildOrderOptions {
  /// A part starts from the most central of its pieces with at least this share of the area
  /// of its largest piece (0: any piece; 1: the largest).
  double large_share = 0.5;
};

/// One seam glued at a step: its printed label, the piece across (already built, or the step's
/// own piece for a seam with itself) and its length on paper.
struct GlueSeam {
  std::string label;
  std::string partner;
  double length_mm = 0.0;
  /// Not a seam to the piece the step attaches to: it closes a loop, glued after those.
  bool closes_loop = false;
};

struct BuildStep {
  int step = 0;  // 1..N
  int part = 0;  // 1..: separate parts of the model, larger first
  std::string piece;
  std::string attach_to;  // the built piece it shares the most seam with; "" first in a part
  /// The attaching seams first (longest first), then those closing loops (longest first).
  std::vector<GlueSeam> seams;
};

struct BuildOrder {
  std::vector<BuildStep> steps;  // one per printed piece, in order
  int parts = 0;

  /// The step of piece `name`, or null when it is not a printed piece.
  const BuildStep* step_of(const std::string& name) const;
};

/// The build order of every printed piece of `layout` (PlacedPiece::seams give the pieces
/// across, PlacedEdge of kind Seam the lengths by label). Joining strips are not pieces of the
/// order. Deterministic: the same layout gives the same order.
/// \pre piece names are unique across the layout (layout_pages numbers them so).
/// \throws InvalidInputException if two printed pieces share a name.
/// Known limit: the lengths are the seams' lengths on paper; where the layout split a strip
/// for the page, its parts are separate pieces joined by their own seam.
BuildOrder build_order(const PatternLayout& layout, const BuildOrderOptions& options = {});

/// "3: glue 7 to 2 along A12, A13, then to 4 along A20, then close it along B1": a step as the
/// assembly guide prints it ("1: start with 5"; "12: start part 2 with 9").
std::string build_step_text(const BuildStep& step);

/// Piece names in number order: by the leading number, then the rest ("2" < "10" < "10a").
bool piece_name_less(const std::string& a, const std::string& b);

}  // namespace papercraft
