#pragma once
// Where to cut a rejected part (paper 3.2.2, with the guards a real mesh needs).
//
// The paper cuts along the iso-line, through the worst point, of the harmonic field f that
// is 0 on the strip's first boundary and 1 on its second. That fails to make progress when
// the worst point sits where f is (nearly) 0 or 1 — for example a long thin tongue of the
// part hanging off one boundary, where f stays near 0 and every iso-line runs along the
// tongue. Then we cut across the part instead, along an iso-line of the harmonic field
// between the part's two (approximately) farthest vertices, through the same point.

#include <functional>
#include <optional>
#include <vector>

#include "core/mesh.h"
#include "core/piece_limits.h"
#include "engine/cut/harmonic.h"

namespace papercraft {

struct WitnessCutOptions {
  CutOptions cut;
  HarmonicOptions harmonic;
  /// Iso-values closer than this to 0 or 1 would shave a sliver off a boundary.
  double margin = 0.05;
  /// A cut is only taken if its smallest piece has at least this fraction of the area.
  double min_piece_fraction = 0.01;
  /// Pieces a person can cut and glue. A cut that would leave a narrower or smaller piece
  /// is moved to the nearest iso-value (of the same field, then of the other) whose pieces
  /// all meet the limits; when none does, the cut whose worst piece falls least short of them
  /// if that is far better than the paper's cut (limit_gain), else the paper's cut.
  PieceLimits limits;
  /// Spacing of the iso-values tried next to a cut that breaks the limits.
  double limit_step = 0.05;
  /// When no cut meets the limits, another cut replaces the paper's only if its worst piece
  /// falls short of them by at most this share of the paper's cut's shortfall.
  double limit_gain = 0.5;
};

/// The area on paper of a piece that is one strip within the tolerance and unfolds in one
/// piece (the refinement's one_flat_strip_area), in model units squared; nullopt when it is
/// not one; an empty function: not known.
using OneStrip = std::function<std::optional<double>(const Mesh&)>;

/// How many holes a piece has, as the refinement sees them: boundary loops that are not its
/// strip's two boundaries (select_strip_boundaries' holes, refine.h), each of which it must
/// cut through again.
using HoleCount = std::function<int(const Mesh&)>;

/// piece_shortfall of `piece` against `limits`, looking ahead with `one_strip` where given, for
/// a piece of min_area to twice min_area (on the surface):
/// - one that is not one strip will be cut again (or split by the unfolding) into pieces that
///   all fall under min_area, so it falls short as they would (1 - area / (2 min_area));
/// - one that is prints as its strip, whose area on paper is the ruled approximation's, not
///   the surface's: over a curved cap the rulings cut across the dome and the strip can be a
///   third smaller. Under min_area it falls short by 1 - paper area / min_area.
double piece_shortfall_ahead(const Mesh& piece, const PieceLimits& limits,
                             const OneStrip& one_strip = {});

/// The worst piece_shortfall_ahead of `pieces`: how far a cut falls short of the limits.
double cut_shortfall(const std::vector<Mesh>& pieces, const PieceLimits& limits,
                     const OneStrip& one_strip = {});

struct WitnessCut {
  std::vector<Mesh> pieces;  // empty when no cut made progress
  double value = 0.0;        // iso-value used
  bool across = false;       // true: the farthest-vertex field was used
};

/// Cuts `part` through `witness` (a point on or near it). `first`/`second` are the strip's
/// boundary vertices (f = 0 and 1). Tries, in order: f through the witness (if it is inside
/// the margins), the farthest-vertex field through the witness, f at 0.5, that field at 0.5;
/// with limits, each followed by the nearest iso-values of its field that meet them (judged
/// by cut_shortfall, with `one_strip`'s look ahead where given).
/// \pre part is connected; first and second are non-empty and disjoint.
WitnessCut cut_through_witness(const Mesh& part, const std::vector<int>& first,
                               const std::vector<int>& second, const Vec3& witness,
                               const WitnessCutOptions& options = {},
                               const OneStrip& one_strip = {});

/// Cuts `part` through the hole `loop`: the iso-line of f halfway between its extremes on the
/// hole. With limits, where that leaves a piece falling short of them, other iso-values
/// through the hole (of f, then of the field between the part's farthest vertices, at shares
/// of their range over the loop) are tried, judged by cut_shortfall with `one_strip`. With
/// `holes`, one whose pieces hold more holes than the middle cut's is passed over: its
/// iso-line crosses the loop but also runs round the part elsewhere, so the hole stays in a
/// piece, which is cut again (femur at 2%: into a 12 mm^2 cap no neighbour takes).
WitnessCut cut_through_hole(const Mesh& part, const std::vector<int>& first,
                            const std::vector<int>& second, const std::vector<int>& loop,
                            const WitnessCutOptions& options = {}, const OneStrip& one_strip = {},
                            const HoleCount& holes = {});

}  // namespace papercraft
