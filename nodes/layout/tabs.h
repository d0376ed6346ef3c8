#pragma once
// Glue tabs: flaps along seam chains, shrunk where they would cover their piece or another
// tab of it, textured with what continues across the seam. Which side of a seam takes them
// is the tab style's choice (tab_styles.h).

#include <optional>
#include <string>
#include <vector>

#include "nodes/layout/layout_types.h"
#include "nodes/layout/piece_shapes.h"
#include "nodes/layout/pieces.h"
#include "nodes/layout/seam_pairing.h"

namespace papercraft::layout_internal {

/// One flap planned on a nearly straight run of a chain's edges (strip frame mm).
struct FlapPlan {
  std::vector<int> edges;  // loop edge indices, in order
  std::vector<Vec2> base;
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> slices;  // convex, one per base edge
  std::vector<int> slice_edges;           // index into `edges` of each slice's base edge
};

/// Plans flaps on the pieces' seam chains and commits them as tabs, each piece's flaps kept
/// clear of the piece and of the flaps it already holds.
class TabPlanner {
 public:
  /// \pre options.tab_width_mm > 0 and tab_angle_degrees in (0, 90].
  TabPlanner(std::vector<Piece>& pieces, const std::vector<StripData>& strips,
             const SeamEdges& seams, const LayoutOptions& options);

  /// The flaps that fit along `chain` (one per nearly straight run, each as high as fits up
  /// to the tab width; where a run has no room, flaps on its edges alone). Nothing is kept.
  std::vector<FlapPlan> plan(const Chain& chain);

  /// The flap that fits on the part (t0, t1) (0 <= t0 < t1 <= 1, from its start) of the first
  /// edge of `edge`: one plan, or none. Nothing is kept.
  std::vector<FlapPlan> plan_part(const Chain& edge, double t0, double t1);

  /// Keeps `plans` on `chain`'s piece: later plans on the piece stay clear of them.
  void reserve(const Chain& chain, const std::vector<FlapPlan>& plans);

  /// Commits `plans` (reserved) to `chain`'s piece as one tab printed `label`.
  void commit(const Chain& chain, std::vector<FlapPlan>& plans, const std::string& label);

  /// The parts of `to` (runs of consecutive edges, in `to`'s order) glued to the edges of
  /// `from` whose position along `from` (0 .. from.count - 1) is marked in `along_from`.
  std::vector<Chain> partner_parts(const Chain& from, const std::vector<char>& along_from,
                                   const Chain& to) const;

 private:
  PieceShapes& shapes_of(int piece);

  std::vector<Piece>& pieces_;
  const std::vector<StripData>& strips_;
  const SeamEdges& seams_;
  double width_, angle_, min_height_, overlap_depth_;
  std::vector<std::optional<PieceShapes>> shapes_;
};

/// The edges of `chain` (positions 0 .. count - 1) that `plans` cover.
std::vector<char> covered_positions(const Chain& chain, const Piece& piece,
                                    const std::vector<FlapPlan>& plans);

}  // namespace papercraft::layout_internal
