#pragma once
// Assembly effort: one number for the work a person does to build a printed pattern, as a sum
// of named terms, each a count or a length on the pages times a weight. The weights are in
// rough minutes of a practised maker's time at the print scale (docs/pieces.md explains each
// default), so a total of 40 reads as "about forty minutes of cutting and gluing", and two
// patterns of one model compare by what they cost a person, not by one count each.
//
//   EffortWeights weights;                          // or from the config's `effort:` map
//   AssemblyEffort effort = assembly_effort(layout, {.min_width_mm = 5, .min_area_mm2 = 100});
//   effort.total;   effort.terms.seam_chains;   ...

#include <string>
#include <vector>

#include "core/pattern.h"

namespace papercraft {

/// What each term costs, per unit (rough minutes). All finite and >= 0.
struct EffortWeights {
  double piece = 1.0;           // one thing to cut out: a printed piece or a joining strip
  double seam = 0.5;            // one seam chain to glue, a seam of a piece with itself too
  double glue_per_metre = 1.0;  // one metre of seam glued (per side pair)
  double sawtooth = 0.5;        // one sawtooth corner on an outline
  double small_piece = 20.0;    // one piece under min_area_mm2 (the limits forbid it)
  double narrow_piece = 20.0;   // one piece narrow over more than max_narrow_share

  /// The name of the first weight that is negative or not a number, "" when all are fine.
  std::string invalid() const;
};

/// The limits a piece on the page is held to, in page millimetres (PaperSpec's).
struct EffortLimits {
  double min_width_mm = 5.0;      // 0: narrowness not counted
  double min_area_mm2 = 100.0;    // 0: smallness not counted
  double max_narrow_share = 0.5;  // PieceLimits::max_narrow_share
};

/// The terms, counted on the pages.
struct EffortTerms {
  int printed_pieces = 0;       // placed pieces, each part of a strip split to fit a page too
  int joining_strips = 0;       // Page::joints
  int things_to_cut = 0;        // printed_pieces + joining_strips
  int seam_chains = 0;          // seams to glue (one per printed seam label)
  int self_seams = 0;           // ... of which both sides lie on one printed piece
  double glue_length_mm = 0.0;  // length of every seam, once (not once per side)
  int sawtooth_corners = 0;     // count_sawtooth_corners over every piece's outline
  int small_pieces = 0;         // printed pieces under min_area_mm2
  int narrow_pieces = 0;        // printed pieces narrower than min_width_mm over too much area
};

struct AssemblyEffort {
  EffortTerms terms;
  EffortWeights weights;
  double total = 0.0;  // the weighted sum
};

/// What the terms cost under `weights`.
double effort_total(const EffortTerms& terms, const EffortWeights& weights);

/// A corner of a closed outline (page mm) is a sawtooth corner where it turns by more than
/// `turn_degrees` and another corner at most `reach_mm` from it along the outline turns by more
/// than `turn_degrees` the other way: a zig-zag or a shallow step nobody cuts cleanly or glues a
/// tab along. Returns how many corners of `loop` are sawtooth corners (both of a pair count).
/// Consecutive points closer than 1e-9 mm count as one; a loop of fewer than 3 points has none.
int count_sawtooth_corners(const std::vector<Vec2>& loop, double turn_degrees = 60.0,
                           double reach_mm = 4.0);

/// The indices into `loop` of its sawtooth corners (count_sawtooth_corners counts them; of
/// consecutive points closer than 1e-9 mm, the last), in order.
std::vector<int> sawtooth_corners(const std::vector<Vec2>& loop, double turn_degrees = 60.0,
                                  double reach_mm = 4.0);

/// Counts the terms on `layout`'s pages and weighs them. A piece's narrowness is measured with
/// narrow_area_fraction at min_width_mm on its page triangles.
AssemblyEffort assembly_effort(const PatternLayout& layout, const EffortLimits& limits,
                               const EffortWeights& weights = {});

}  // namespace papercraft
