#pragma once
// The label placer behind place_labels (label_placement.h): its state over one pass, the one
// clearance test and the candidate generators. Its members are defined in label_placement.cpp
// (the number, the spots along and beside the seam, the last resorts) and label_leaders.cpp
// (the spots reached by a leader line).

#include <array>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "nodes/layout/label_placement.h"
#include "nodes/layout/leader_router.h"
#include "nodes/layout/piece_shapes.h"

namespace papercraft::layout_internal {

using Box = std::array<Vec2, 4>;

/// The boundary segments of a piece and its flaps' outer chains (mm, strip frame): no text
/// may cross them.
std::vector<std::array<Vec2, 2>> cut_lines(const StripData& data, const Piece& piece);

/// True when p lies inside the polygon (even-odd rule).
bool point_in_polygon(const Vec2& p, const std::vector<Vec2>& polygon);

/// The middle of the outer edge of a flap of the tab `label` carries on this piece, that
/// edge's direction and its normal pointing away from the tab: where a leader leaves a seam
/// walled in by its own tab.
struct TabEdge {
  Vec2 middle, along, outward;
};
std::vector<TabEdge> outer_tab_edges(const Piece& piece, const std::string& label);

// Where a text box may go.
enum class Ground {
  Piece,   // on the piece's paper (box_on_piece)
  Beside,  // off it: meeting none of its triangles and tabs (text printed beside the piece)
};

// The seam label being placed and what its candidates are made from.
struct SeamLabel {
  std::size_t n = 0;  // its position in piece.labels
  PieceLabel* label = nullptr;
  const Chain* chain = nullptr;
  double total = 0;                // the chain's length
  std::vector<double> sizes;       // its size, then smaller down to the smallest text
  Vec2 chord = Vec2::Zero();       // from the chain's first point to its last
  std::vector<TabEdge> tab_edges;  // outer edges of its tab on this piece
};

// One pass of place_labels over one piece (see there). Every spot a generator offers passes
// clear_at (or, for a flap of the seam's own tab, clear_on_flap); the first that does is kept.
class LabelPlacer {
 public:
  LabelPlacer(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
              const OrientedBox& box, const LayoutOptions& options,
              std::vector<std::string>& warnings)
      : data_(data),
        piece_(piece),
        chains_(chains),
        box_(box),
        options_(options),
        warnings_(warnings),
        shapes_(piece_shapes(data, piece)),
        lines_(cut_lines(data, piece)),
        smallest_(options.min_text_mm),
        router_(lines_, 1.0) {
    for (const Flap& flap : piece.flaps) {
      if (flap.base.size() < 2 || flap.outer.empty()) continue;
      flaps_.emplace_back(flap.base.rbegin(), flap.base.rend());
      flaps_.back().insert(flaps_.back().end(), flap.outer.begin(), flap.outer.end());
      flap_boxes_.emplace_back();
      for (const Vec2& p : flaps_.back()) flap_boxes_.back().add(p);
    }
  }

  Placement run(bool number_last);

 private:
  // The clearance test. Clear of the text placed so far, crossed by no cut line, and on the
  // ground asked for.
  bool clear_of_text(const Box& candidate) const {
    for (const auto& other : taken_)
      if (convex_overlap(candidate.data(), 4, other.data(), 4, -kTextGap)) return false;
    return true;
  }
  bool beside(const Box& candidate) const;
  bool clear_at(const Box& candidate, Ground ground) const {
    if (ground == Ground::Piece)
      return box_on_piece(candidate, shapes_) && clear_of_text(candidate) &&
             router_.box_clear(candidate);
    return clear_of_text(candidate) && router_.box_clear(candidate) && beside(candidate);
  }
  // On a flap of the seam's own tab: inside its polygon and clear of text.
  bool clear_on_flap(const Box& candidate, const std::vector<Vec2>& polygon) const {
    bool inside = true;
    for (const Vec2& corner : candidate) inside = inside && point_in_polygon(corner, polygon);
    bool free = true;
    for (const auto& other : taken_)
      free = free && !convex_overlap(candidate.data(), 4, other.data(), 4, -kTextGap);
    return inside && free;
  }

  // The piece number's generators, in order; the last always places it.
  bool number_at_incentres();
  bool number_on_grid();
  bool number_beside_edges();
  void number_crowded();
  void place_number();

  // A seam label's generators, in order (kLabelGenerators).
  bool as_given(SeamLabel& s);
  bool along_seam(SeamLabel& s);
  bool on_own_tab(SeamLabel& s);
  bool beside_seam(SeamLabel& s);
  bool leader_from_seam(SeamLabel& s);
  bool leader_from_tab(SeamLabel& s);
  bool leader_inward(SeamLabel& s);
  bool leader_from_grid(SeamLabel& s);
  bool leader_round_corner(SeamLabel& s);
  bool named_by_slit_twin(SeamLabel& s);
  bool near_without_leader(SeamLabel& s);
  bool fewest_overlaps(SeamLabel& s);
  using Generator = bool (LabelPlacer::*)(SeamLabel&);
  static constexpr std::array<Generator, 12> kLabelGenerators = {&LabelPlacer::as_given,
                                                                 &LabelPlacer::along_seam,
                                                                 &LabelPlacer::on_own_tab,
                                                                 &LabelPlacer::beside_seam,
                                                                 &LabelPlacer::leader_from_seam,
                                                                 &LabelPlacer::leader_from_tab,
                                                                 &LabelPlacer::leader_inward,
                                                                 &LabelPlacer::leader_from_grid,
                                                                 &LabelPlacer::leader_round_corner,
                                                                 &LabelPlacer::named_by_slit_twin,
                                                                 &LabelPlacer::near_without_leader,
                                                                 &LabelPlacer::fewest_overlaps};

  // Puts the label at `centre` and takes its box.
  void put(SeamLabel& s, const Vec2& centre, const Vec2& direction, double size, bool outside,
           const Box& candidate) {
    PieceLabel& label = *s.label;
    label.position = centre;
    label.direction = direction;
    label.size = size;
    label.outside = outside;
    taken_.push_back(candidate);
  }

  // Leader lines.
  template <class LineOk>
  bool leader_at(SeamLabel& s, const Vec2& anchor, const Vec2& centre, const Vec2& along,
                 const Box& candidate, bool outside, LineOk line_ok);
  template <class BoxOk, class LineOk>
  bool leader_to(SeamLabel& s, const Vec2& anchor, const Vec2& along, const Vec2& normal,
                 std::initializer_list<double> radii, bool outside, BoxOk box_ok, LineOk line_ok);
  bool leader_outside(SeamLabel& s, const Vec2& anchor, const Vec2& along, const Vec2& outward);
  bool off_piece(const Vec2& start, const Vec2& end) const;
  bool on_piece(const Vec2& start, const Vec2& end) const;

  // Points along a chain.
  std::optional<Vec2> chain_point(const Chain& chain, double at, Vec2* direction) const;
  Vec2 point_at(const SeamLabel& s, double at, Vec2* direction) const {
    if (const auto point = chain_point(*s.chain, at, direction)) return *point;
    *direction = Vec2::UnitX();
    return s.label->position;
  }
  bool slit(const Chain& one, const Chain& other) const;
  bool slit_twins(std::size_t m, std::size_t n) const;

  const StripData& data_;
  Piece& piece_;
  const std::vector<Chain>& chains_;
  const OrientedBox& box_;
  const LayoutOptions& options_;
  std::vector<std::string>& warnings_;
  const PieceShapes shapes_;
  const std::vector<std::array<Vec2, 2>> lines_;
  const double smallest_;
  const LeaderRouter router_;
  std::vector<std::vector<Vec2>> flaps_;  // the flaps' polygons
  std::vector<Box2> flap_boxes_;  // each flap's bounding box: a box beyond it meets none of it
  std::vector<Box> taken_;        // the boxes of the texts and leaders placed so far
  Placement placement_;
  std::vector<char> printed_, clear_spot_, detached_;  // per label; detached: near its seam only
};

}  // namespace papercraft::layout_internal
