#include "engine/refine/rejected_cut.h"

#include "engine/refine/maximal_strip.h"

namespace papercraft {

WitnessCut cut_rejected_part(const Mesh& part, const std::vector<int>& first, bool first_closed,
                             const std::vector<int>& second, bool second_closed,
                             const std::vector<int>* hole, const Vec3& witness, double tolerance,
                             const RejectedCutOptions& options, const TwistOptions& twist,
                             const DecideOptions& decide, const PieceLimits& limits,
                             const OneStrip& one_strip, const HoleCount& holes) {
  WitnessCutOptions cut_options = options.cut;
  cut_options.limits = limits;
  cut_options.cut.snap_distance = options.snap_tolerance * tolerance;
  const bool search = hole == nullptr && options.search_steps > 0 &&
                      static_cast<long>(part.n_faces()) <= options.search_max_faces;
  auto maximal_strip = [&](double min_strip_fraction) {
    MaximalStripOptions settings;
    settings.cut = cut_options;
    settings.steps = options.search_steps;
    settings.min_strip_fraction = min_strip_fraction;
    settings.twist = twist;
    settings.decide = decide;
    return cut_maximal_strip(part, first, first_closed, second, second_closed, tolerance, settings,
                             one_strip);
  };
  WitnessCut cut;
  if (search) cut = maximal_strip(options.search_min_fraction);
  if (cut.pieces.empty()) {
    cut = hole ? cut_through_hole(part, first, second, *hole, cut_options, one_strip, holes)
               : cut_through_witness(part, first, second, witness, cut_options, one_strip);
  }
  // No iso-line through the worst point splits the part: a thin strip next to a boundary is
  // still progress (within the limits if one is, else however thin).
  if (cut.pieces.empty() && search && options.search_min_fraction > 0.0) cut = maximal_strip(0.0);
  if (cut.pieces.empty() && search && cut_options.limits.active()) {
    cut_options.limits = {};
    cut = maximal_strip(0.0);
  }
  return cut;
}

}  // namespace papercraft
