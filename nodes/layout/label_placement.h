#pragma once
// One pass of arrange_labels (annotations.h): the piece number and the seam labels placed in
// turn, each at the first spot a list of candidate generators offers that passes the one
// clearance test.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nodes/layout/layout_types.h"
#include "nodes/layout/pieces.h"
#include "nodes/layout/polygon_2d.h"
#include "nodes/layout/seam_pairing.h"

namespace papercraft::layout_internal {

/// Texts clear each other by at least this (mm). Boxes that only touch in the piece's plane
/// can overlap by a rounding error once turned onto the page (and counted so).
inline constexpr double kTextGap = 1e-6;

/// The inscribed circle of triangle t of the strip: its centre and radius; none for a
/// triangle whose corners coincide.
std::optional<std::pair<Vec2, double>> incircle(const StripData& data, int t);

/// What one pass of place_labels left: the positions (in the labels it was given) of the
/// labels it kept, in order, and of those printed with no spot clear of other text and lines.
struct Placement {
  std::vector<std::size_t> kept;
  std::vector<std::size_t> crowded;
  bool number_crowded = false;  // the number found no clear spot either
  std::size_t misses() const { return crowded.size() + (number_crowded ? 1 : 0); }
};

/// One pass of arrange_labels: the number, then the labels in their order, each taking the
/// first clear spot left by those before it (the number after them, with `number_last`).
/// Labels dropped (one side of a slit named by the other) are removed from piece.labels.
Placement place_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                       const OrientedBox& box, const LayoutOptions& options, bool number_last,
                       std::vector<std::string>& warnings);

}  // namespace papercraft::layout_internal
