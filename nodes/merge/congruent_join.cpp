// merge_congruent: the paper's merge (section 3.4), joining strips whose shared boundaries are
// congruent in the plane, the pair with the longest shared length first.
#include <set>
#include <utility>

#include "core/flat_boundary.h"
#include "core/seams.h"
#include "nodes/merge/chains.h"
#include "nodes/merge/congruent.h"
#include "nodes/merge/rigid_join.h"
#include "nodes/merge/validate.h"

namespace papercraft {

using merge_detail::PairCandidate;
using merge_detail::shared_boundaries;
using merge_detail::try_merge;
using merge_detail::validate;

std::vector<FlatStrip> merge_congruent(std::vector<FlatStrip> strips, const MergeOptions& options) {
  validate(strips, options);
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);

  // A pair that failed is not tried again until one of its strips changes.
  std::vector<int> version(strips.size());
  for (std::size_t i = 0; i < strips.size(); ++i) version[i] = static_cast<int>(i);
  int next_version = static_cast<int>(strips.size());
  std::set<std::pair<int, int>> failed;
  for (bool merged_any = true; merged_any;) {
    merged_any = false;
    for (PairCandidate& candidate : shared_boundaries(strips)) {
      std::pair<int, int> key{version[candidate.x], version[candidate.y]};
      if (failed.count(key)) continue;
      FlatStrip merged;
      if (!try_merge(strips[candidate.x], strips[candidate.y], std::move(candidate.chains), options,
                     merged)) {
        failed.insert(key);
        continue;
      }
      strips[candidate.x] = std::move(merged);
      version[candidate.x] = next_version++;
      strips.erase(strips.begin() + candidate.y);
      version.erase(version.begin() + candidate.y);
      merged_any = true;
      break;
    }
  }
  label_seams(strips);
  return strips;
}

}  // namespace papercraft
