#pragma once
// The strips as the layout works on them (StripData: page millimetres and edge lookups) and
// the pieces of paper cut from them (Piece: boundary loops, flaps, tabs, labels, marks).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/pattern.h"
#include "core/strip.h"

namespace papercraft::layout_internal {

/// A strip scaled to millimetres, with its usable triangles and directed-edge lookups.
struct StripData {
  const FlatStrip* strip = nullptr;
  std::vector<Vec2> points;                                    // vertices2d in mm
  std::vector<int> triangles;                                  // usable triangle indices
  std::unordered_map<std::uint64_t, int> owner;                // directed edge -> triangle
  std::unordered_map<std::uint64_t, int> boundary_of;          // directed edge -> boundary index
  std::unordered_map<std::uint64_t, std::string> split_label;  // unordered inner edge
  bool missing_boundary_warned = false;
  int splits = 0;  // split seams made so far (labelled <strip id>-1, -2, ...)
  /// Its triangles were divided (divide_triangles): a strip too large for the page is cut
  /// across its long axis, not along a ruling (one wider than the page is long first along
  /// that axis into slabs that are not).
  bool divided = false;
};

/// An edge of a piece's boundary loop, with the seam label it carries and its flap.
struct PieceEdge {
  int v0 = -1, v1 = -1;
  EdgeKind kind = EdgeKind::Cut;
  std::string label;    // as given (or a split's label)
  std::string printed;  // as printed
  int flap = -1;        // index into Piece::flaps: a flap over several edges covering this one
  bool flap_first = false;
  std::vector<int> edge_flaps;  // flaps on this edge alone (all of it or parts), in order along it
};

/// One flap of a tab: a polygon on a nearly straight run of seam edges, in the strip frame.
struct Flap {
  std::vector<Vec2> base;             // p_a .. p_b+1 (or part of one edge), strip frame mm
  std::vector<Vec2> outer;            // q_a .. q_b+1
  int tab = -1;                       // index into Piece::tabs
  std::vector<TexturePatch> texture;  // strip frame mm
};

/// A glue tab: the flaps along one seam chain, printed with the seam's label.
struct PieceTab {
  std::string label;
  std::vector<int> flaps;
};

/// A seam label or piece number in the strip frame (direction along the text).
struct PieceLabel {
  std::string text;
  Vec2 position;
  Vec2 direction;
  double size;
  int chain = -1;  // the seam chain it names
  /// Printed beside the piece, on the paper around it, where the piece has no room for it
  /// (nesting keeps other pieces off it).
  bool outside = false;
  /// For a label printed away from its seam: a thin line from the seam's middle (first
  /// point) to the text box, so the reader knows which seam it names. Empty: none.
  std::vector<Vec2> leader;
};

/// The triangles of a strip printed as one piece of paper (the whole strip or part of a split).
struct Piece {
  int strip = -1;  // index into strips
  int index = 0;
  int count = 1;
  std::string name;  // as printed: "12", or "12a", "12b" for the pieces of a split strip
  bool joint = false;  // a joining strip (name: the seam's label), placed in Page::joints
  std::vector<int> triangles;
  std::vector<std::vector<PieceEdge>> loops;
  std::vector<Flap> flaps;
  std::vector<PieceTab> tabs;
  std::vector<PieceLabel> labels;
  std::optional<PieceLabel> number;        // set by arrange_labels
  std::vector<std::array<Vec2, 2>> marks;  // strip frame mm (see PlacedPiece::marks)
  std::vector<PieceSeam> seams;
};

/// The printed name of piece `index` of `count` of the strip numbered `number` (1-based):
/// "12", or "12a", "12b", ... (then "12aa", ...) when the strip was split.
std::string piece_name(int number, int index, int count);

/// "strip <id>", as messages name a strip.
std::string strip_name(const FlatStrip& strip);

/// \throws InvalidInputException when the strip's sizes, indices or coordinates are invalid.
void validate_strip(const FlatStrip& strip);

/// The strip in millimetres with its edge lookups; degenerate triangles are left out.
/// \throws InvalidInputException for a clockwise triangle, an edge two triangles use in one
///         direction or a boundary edge that is not one with the strip on its left.
StripData prepare_strip(const FlatStrip& strip, double mm_per_unit);

/// The corners (mm) of `triangles`, each vertex once (in the order the triangles first use it).
std::vector<Vec2> piece_points(const StripData& data, const std::vector<int>& triangles);

/// Boundary loops of a set of triangles, following each boundary edge to the next around
/// their shared vertex through the set's triangles (right at pinch vertices); largest area
/// first. Warns once per strip for a boundary edge missing from the strip's boundary list.
std::vector<std::vector<PieceEdge>> piece_loops(StripData& data, const std::vector<int>& triangles,
                                                std::vector<std::string>& warnings);

}  // namespace papercraft::layout_internal
