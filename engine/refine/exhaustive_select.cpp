#include "engine/refine/exhaustive_select.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <string>
#include <utility>

#include "core/bvh.h"
#include "core/errors.h"
#include "engine/ruled/part_strip.h"

namespace papercraft {
namespace {

void check_options(const ExhaustiveSelectOptions& options) {
  if (!std::isfinite(options.error_bound) || options.error_bound < 0.0) {
    throw InvalidInputException("select.exhaustive: error_bound must be finite and >= 0, got " +
                                std::to_string(options.error_bound));
  }
}

double error_bound_for(const TriangleMesh& part, double error_bound) {
  if (error_bound > 0.0) return error_bound;
  const auto box = bounding_box(part.vertices);
  const double diagonal = (box[1] - box[0]).norm();
  // A part of zero extent: any positive bound is met at once.
  return diagonal > 0.0 ? 0.01 * diagonal : 1.0;
}

std::vector<ScoredSelection> score(const Mesh& part, std::vector<BoundarySelection> selections,
                                   const ExhaustiveSelectOptions& options) {
  TriangleMesh part_mesh = to_triangle_mesh(part);
  const double error_bound = error_bound_for(part_mesh, options.error_bound);
  const TriangleBvh part_tree(std::move(part_mesh));
  std::vector<ScoredSelection> scores(selections.size());
  tbb::parallel_for(std::size_t{0}, selections.size(), [&](std::size_t k) {
    BoundarySelection& selection = selections[k];
    RuledStrip strip = part_strip(
        part, selection.first, selection_polyline(part, selection.first, selection.first_closed),
        selection.second, selection_polyline(part, selection.second, selection.second_closed),
        options.twist);
    HausdorffResult result;
    if (options.decide.sampled) {
      result = sampled_hausdorff_distance(part_tree.mesh(), strip.mesh, options.decide.sampling);
    } else {
      const TriangleBvh strip_tree(std::move(strip.mesh));
      result =
          certified_hausdorff_distance(part_tree, strip_tree, error_bound, options.decide.bounded);
    }
    scores[k] = {std::move(selection), result.lower, result.upper, result.certified};
  });
  return scores;
}

}  // namespace

std::vector<ScoredSelection> score_selections(const Mesh& part,
                                              const ExhaustiveSelectOptions& options) {
  check_options(options);
  return score(part, candidate_selections(part), options);
}

BoundarySelection select_exhaustive(const Mesh& part, const ExhaustiveSelectOptions& options) {
  check_options(options);
  auto selections = candidate_selections(part);
  if (selections.size() == 1) return std::move(selections.front());
  auto scores = score(part, std::move(selections), options);
  std::size_t best = 0;
  for (std::size_t k = 1; k < scores.size(); ++k) {
    if (scores[k].upper < scores[best].upper) best = k;
  }
  return std::move(scores[best].selection);
}

}  // namespace papercraft
