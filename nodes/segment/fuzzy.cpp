#include "nodes/segment/fuzzy.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <numeric>
#include <queue>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>

#include "core/errors.h"
#include "engine/refine/refine.h"
#include "nodes/segment/face_regions.h"
#include "nodes/segment/fuzzy_decomposition.h"
#include "nodes/segment/labelled_surface.h"
#include "nodes/segment/straighten.h"

namespace papercraft {
namespace {

using fuzzy_internal::decompose;
using fuzzy_internal::region_graph;
using fuzzy_internal::RegionGraph;

// count_strips, remembered: the same region is judged whole at one level, as a part of
// several candidate decompositions, again as emitted, and by the hierarchies of the
// alternative settings. An entry holds the exact count if it is at most the cap it was
// computed with, else only that the count exceeds that cap, so a hit returns what a fresh call
// would (the result does not depend on the threads). Keyed by an FNV-1a hash of the part's
// coordinates and triangles: parts cut out of the same faces the same way are bit-identical meshes.
// A collision (about 2^-64 a pair) could only mislead the choice of parts, never what is certified:
// every strip is still decided against its own part.
class EstimateCache {
 public:
  EstimateCache(double tolerance, const RefineOptions& refine, const PieceLimits& limits)
      : refine_(at_tolerance(refine, tolerance)), limits_(limits) {}

  int estimate(const Mesh& part, int cap) {
    const std::uint64_t key = geometry_hash(part);
    {
      std::lock_guard lock(mutex_);
      const auto it = entries_.find(key);
      if (it != entries_.end()) {
        const auto [count, computed_cap] = it->second;
        if (count <= computed_cap) return count <= cap ? count : cap + 1;
        if (cap <= computed_cap) return cap + 1;
      }
    }
    const int count = count_strips(part, refine_, cap, limits_);
    std::lock_guard lock(mutex_);
    const auto [it, inserted] = entries_.try_emplace(key, count, cap);
    if (!inserted) {
      const auto [known, known_cap] = it->second;
      if (known > known_cap && (count <= cap || cap > known_cap)) it->second = {count, cap};
    }
    return count;
  }

 private:
  static std::uint64_t geometry_hash(const Mesh& part) {
    std::uint64_t hash = 1469598103934665603ull;
    auto mix = [&](std::uint64_t word) {
      for (int byte = 0; byte < 8; ++byte) {
        hash ^= (word >> (8 * byte)) & 0xff;
        hash *= 1099511628211ull;
      }
    };
    mix(part.n_vertices());
    mix(part.n_faces());
    for (auto v : part.vertices()) {
      for (int i = 0; i < 3; ++i) {
        std::uint64_t bits;
        const double x = part.point(v)[i];
        std::memcpy(&bits, &x, sizeof bits);
        mix(bits);
      }
    }
    for (auto f : part.faces()) {
      for (auto v : part.fv_range(f)) mix(static_cast<std::uint64_t>(v.idx()));
    }
    return hash;
  }

  const RefineOptions refine_;
  const PieceLimits limits_;
  std::mutex mutex_;
  std::unordered_map<std::uint64_t, std::pair<int, int>> entries_;  // count, cap
};

class Hierarchy {
 public:
  Hierarchy(const Mesh& mesh, const FaceGraph& graph, const FuzzySegmentOptions& options,
            EstimateCache& estimates)
      : mesh_(mesh),
        graph_(graph),
        options_(options),
        min_area_(options.min_area_fraction * graph.total_area),
        estimates_(estimates) {}

  // Leaf regions of `faces` (sorted model faces, connected), in a deterministic order.
  // Judged by strips, a decomposition is kept only if it costs at most `cap` strips.
  std::vector<std::vector<int>> leaves(const std::vector<int>& faces, int depth,
                                       int cap = std::numeric_limits<int>::max() / 2) const {
    if (judge_by_strips()) return cheapest(faces, depth, cap).leaves;
    const std::vector<std::vector<std::vector<int>>> candidates = decompositions(faces, depth);
    if (candidates.empty()) return {faces};
    const std::vector<std::vector<int>>& children = candidates.back();
    std::vector<std::vector<std::vector<int>>> results(children.size());
    tbb::parallel_for(std::size_t{0}, children.size(),
                      [&](std::size_t c) { results[c] = leaves(children[c], depth + 1); });
    std::vector<std::vector<int>> all;
    for (auto& result : results)
      for (auto& leaf : result) all.push_back(std::move(leaf));
    return all;
  }

  // The hierarchy only ever merges regions of one parent; two leaves of different branches (a
  // neck on one side of a level's boundary and the head on the other) may still be cheaper as
  // one region. Merges the pair of adjacent leaves that saves the most estimated strips, until
  // no pair saves any (ties: the first pair in leaf order). Deterministic.
  std::vector<std::vector<int>> merge_cheaper_neighbours(
      std::vector<std::vector<int>> leaves) const {
    constexpr int kUnbounded = std::numeric_limits<int>::max() / 2;
    std::vector<int> cost(leaves.size());
    tbb::parallel_for(std::size_t{0}, leaves.size(),
                      [&](std::size_t i) { cost[i] = strips_of(leaves[i], kUnbounded); });
    for (;;) {
      std::vector<int> leaf_of(graph_.areas.size(), -1);
      for (std::size_t i = 0; i < leaves.size(); ++i)
        for (int f : leaves[i]) leaf_of[f] = static_cast<int>(i);
      std::set<std::pair<int, int>> adjacent;
      for (std::size_t i = 0; i < leaves.size(); ++i) {
        for (int f : leaves[i]) {
          for (int a : graph_.face_arcs[f]) {
            const int j = leaf_of[graph_.other_face(a, f)];
            if (j > static_cast<int>(i)) adjacent.insert({static_cast<int>(i), j});
          }
        }
      }
      const std::vector<std::pair<int, int>> pairs(adjacent.begin(), adjacent.end());
      std::vector<int> merged_cost(pairs.size());
      tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t k) {
        const auto [i, j] = pairs[k];
        std::vector<int> faces = leaves[i];
        faces.insert(faces.end(), leaves[j].begin(), leaves[j].end());
        std::sort(faces.begin(), faces.end());
        merged_cost[k] = strips_of(faces, cost[i] + cost[j] - 1);
      });
      int best = -1, best_saving = 0;
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        const int saving = cost[pairs[k].first] + cost[pairs[k].second] - merged_cost[k];
        if (saving > best_saving) {
          best_saving = saving;
          best = static_cast<int>(k);
        }
      }
      if (best < 0) return leaves;
      const auto [i, j] = pairs[best];
      leaves[i].insert(leaves[i].end(), leaves[j].begin(), leaves[j].end());
      std::sort(leaves[i].begin(), leaves[i].end());
      cost[i] = merged_cost[best];
      leaves.erase(leaves.begin() + j);
      cost.erase(cost.begin() + j);
    }
  }

  // The connected pieces (through arcs) of each label of `faces`, in order of lowest face.
  std::vector<std::vector<int>> connected_groups(const std::vector<int>& faces,
                                                 const std::vector<int>& label) const {
    std::map<int, int> seen;  // face -> group
    std::vector<std::vector<int>> result;
    for (int seed : faces) {
      if (seen.count(seed)) continue;
      const int group = static_cast<int>(result.size());
      result.push_back({seed});
      seen[seed] = group;
      for (std::size_t i = 0; i < result[group].size(); ++i) {
        const int f = result[group][i];
        for (int a : graph_.face_arcs[f]) {
          const int g = graph_.other_face(a, f);
          if (label[g] != label[f] || seen.count(g)) continue;
          seen[g] = group;
          result[group].push_back(g);
        }
      }
      std::sort(result[group].begin(), result[group].end());
    }
    return result;
  }

  // Estimated strips of the region `faces` (its boundaries as they are, not straightened),
  // counting no further than cap + 1.
  int strips_of(const std::vector<int>& faces, int cap) const {
    if (cap < 1) return cap + 1;  // every region makes a strip
    std::vector<int> label(graph_.areas.size(), -1);
    for (int f : faces) label[f] = 0;
    LabelledSoup surface = labelled_surface(mesh_, label);
    std::size_t kept = 0;
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
      if (surface.labels[t] < 0) continue;
      surface.triangles[kept] = surface.triangles[t];
      surface.origin_face[kept] = surface.origin_face[t];
      surface.labels[kept] = surface.labels[t];
      ++kept;
    }
    surface.triangles.resize(kept);
    surface.origin_face.resize(kept);
    surface.labels.resize(kept);
    return strips_of(build_pieces(surface), cap);
  }

  int strips_of(const std::vector<Mesh>& parts, int cap) const {
    int strips = 0;
    for (const Mesh& part : parts) {
      if (cap - strips < 1) return cap + 1;
      strips += estimates_.estimate(part, cap - strips);
      if (strips > cap) return cap + 1;
    }
    return strips;
  }

 private:
  struct Choice {
    std::vector<std::vector<int>> leaves;
    int cost = 0;  // estimated strips; above the cap when it was exceeded
  };

  // The candidate decompositions of a region one level down (each a list of face groups with
  // at least two), the rule's choice last; none if the region is not to be split.
  std::vector<std::vector<std::vector<int>>> decompositions(const std::vector<int>& faces,
                                                            int depth) const {
    if (!may_split(faces, depth)) return {};
    const RegionGraph region = region_graph(graph_, faces, options_);
    std::vector<int> label(graph_.areas.size(), -1);
    const std::vector<int> local_label = decompose(region, graph_, options_);
    for (int i = 0; i < region.size(); ++i) label[faces[i]] = local_label[i];
    label = consolidate_regions(graph_, label, min_area_);
    std::vector<std::vector<std::vector<int>>> candidates;
    auto add = [&](std::vector<std::vector<int>> candidate) {
      if (candidate.size() < 2) return;
      if (std::find(candidates.begin(), candidates.end(), candidate) != candidates.end()) return;
      candidates.push_back(std::move(candidate));
    };
    if (options_.parts == 0) {
      if (judge_by_strips()) add(groups(faces, label));
      merge_weak_boundaries(faces, label);
      label = consolidate_regions(graph_, label, min_area_);
    }
    add(groups(faces, label));
    if (options_.parts == 0 && judge_by_strips() && options_.single_part_candidates) {
      // Also each part of those decompositions alone, the rest of the region left whole
      // (one piece per connected remainder).
      const std::size_t decompositions = candidates.size();
      for (std::size_t c = 0; c < decompositions; ++c) {
        if (candidates[c].size() < 3) continue;
        const std::vector<std::vector<int>> parts = candidates[c];
        for (const auto& part : parts) {
          for (int f : faces) label[f] = 1;
          for (int f : part) label[f] = 0;
          add(connected_groups(faces, label));
        }
      }
    }
    if (options_.parts == 0 && judge_by_strips() && options_.two_way_candidate) {
      // Also the two-way split between the region's farthest faces.
      FuzzySegmentOptions two = options_;
      two.parts = 2;
      std::vector<int> split(graph_.areas.size(), -1);
      const std::vector<int> local_split = decompose(region, graph_, two);
      for (int i = 0; i < region.size(); ++i) split[faces[i]] = local_split[i];
      add(groups(faces, consolidate_regions(graph_, split, min_area_)));
    }
    return candidates;
  }

  // The leaves of `faces` that the refinement makes the fewest strips of: the region whole, or
  // one of its decompositions with each part's own cheapest leaves. Ties keep fewer parts. Only
  // costs up to `cap` are told apart.
  //
  // With more than one thread the candidates are judged side by side, each against the region
  // whole rather than against the best candidate before it: more work, the same choice (the
  // first candidate of least cost; a choice costing at most its cap does not depend on it).
  Choice cheapest(const std::vector<int>& faces, int depth, int cap) const {
    Choice best{{faces}, strips_of(faces, cap)};
    if (best.cost <= 1) return best;
    const auto candidates = decompositions(faces, depth);
    auto judge = [&](const std::vector<std::vector<int>>& candidate, int bound) {
      Choice split;
      for (const auto& group : candidate) {
        Choice child = cheapest(group, depth + 1, bound - split.cost - 1);
        split.cost += child.cost;
        if (split.cost >= bound) break;
        for (auto& leaf : child.leaves) split.leaves.push_back(std::move(leaf));
      }
      return split;
    };
    if (candidates.size() > 1 && tbb::this_task_arena::max_concurrency() > 1) {
      std::vector<Choice> splits(candidates.size());
      const int bound = std::min(best.cost, cap + 1);
      tbb::parallel_for(std::size_t{0}, candidates.size(),
                        [&](std::size_t c) { splits[c] = judge(candidates[c], bound); });
      for (Choice& split : splits) {
        if (split.cost < std::min(best.cost, cap + 1)) best = std::move(split);
      }
      return best;
    }
    for (const auto& candidate : candidates) {
      const int bound = std::min(best.cost, cap + 1);  // to beat
      Choice split = judge(candidate, bound);
      if (split.cost < bound) best = std::move(split);
    }
    return best;
  }

  bool judge_by_strips() const { return options_.strip_tolerance > 0; }

  // The faces of each label, labels in order of first appearance in `faces`.
  static std::vector<std::vector<int>> groups(const std::vector<int>& faces,
                                              const std::vector<int>& label) {
    std::map<int, int> index;
    std::vector<std::vector<int>> result;
    for (int f : faces) {
      auto [it, inserted] = index.emplace(label[f], static_cast<int>(result.size()));
      if (inserted) result.emplace_back();
      result[it->second].push_back(f);
    }
    return result;
  }

  bool may_split(const std::vector<int>& faces, int depth) const {
    if (faces.size() < 4) return false;
    if (options_.parts > 0) return depth == 0;
    if (depth >= options_.max_depth) return false;
    double area = 0;
    for (int f : faces) area += graph_.areas[f];
    return area >= 2 * min_area_;
  }

  // Katz & Tal stop decomposing a patch whose dihedral angles vary little; on a finely
  // tessellated smooth surface every dihedral angle is small however deep its concavities, so
  // instead each boundary is judged: it stays if it is a neck or a concave crease (see
  // FuzzySegmentOptions), else the parts beside the weakest boundary are merged, until every
  // boundary left is one of these. A smooth convex patch thus ends up whole.
  void merge_weak_boundaries(const std::vector<int>& faces, std::vector<int>& label) const {
    const double crease = -options_.crease_angle_degrees * std::numbers::pi / 180.0;
    for (;;) {
      std::map<int, double> area;
      struct Boundary {
        double length = 0;
        double signed_angle = 0;     // length-weighted sum; concave negative
        Vec3 moment = Vec3::Zero();  // length-weighted sum of edge midpoints
        double spread = 0;           // length-weighted sum of distances from their centroid
      };
      std::map<std::pair<int, int>, Boundary> boundaries;
      auto for_each_boundary_arc = [&](auto visit) {
        for (int f : faces) {
          for (int a : graph_.face_arcs[f]) {
            const int g = graph_.other_face(a, f);
            if (label[g] < 0 || label[f] >= label[g]) continue;
            visit(boundaries[{label[f], label[g]}], graph_.arcs[a]);
          }
        }
      };
      auto middle = [&](const FaceArc& arc) {
        return Vec3(0.5 * (to_eigen(mesh_.point(Mesh::VertexHandle(arc.vertex_a))) +
                           to_eigen(mesh_.point(Mesh::VertexHandle(arc.vertex_b)))));
      };
      for (int f : faces) area[label[f]] += graph_.areas[f];
      for_each_boundary_arc([&](Boundary& boundary, const FaceArc& arc) {
        boundary.length += arc.length;
        boundary.signed_angle += arc.length * (arc.concave ? -arc.angle : arc.angle);
        boundary.moment += arc.length * middle(arc);
      });
      for_each_boundary_arc([&](Boundary& boundary, const FaceArc& arc) {
        boundary.spread += arc.length * (middle(arc) - boundary.moment / boundary.length).norm();
      });
      double weakest = options_.neck_ratio;
      std::pair<int, int> merge{-1, -1};
      for (const auto& [pair, boundary] : boundaries) {
        if (boundary.signed_angle <= crease * boundary.length) continue;
        // The size of the boundary as 2 pi times its mean radius: exact for a circle, and blind
        // to the staircase of mesh edges that a cut follows.
        const double size = 2 * std::numbers::pi * boundary.spread / boundary.length;
        const double ratio = size * size / std::min(area[pair.first], area[pair.second]);
        if (ratio > weakest) {
          weakest = ratio;
          merge = pair;
        }
      }
      if (merge.first < 0) return;
      for (int f : faces)
        if (label[f] == merge.second) label[f] = merge.first;
    }
  }

  const Mesh& mesh_;
  const FaceGraph& graph_;
  const FuzzySegmentOptions& options_;
  double min_area_;
  EstimateCache& estimates_;
};

FuzzySegmentOptions with_alternative(const FuzzySegmentOptions& options,
                                     const FuzzyAlternative& alternative) {
  FuzzySegmentOptions run = options;
  run.angular_weight = alternative.angular_weight.value_or(options.angular_weight);
  run.convex_eta = alternative.convex_eta.value_or(options.convex_eta);
  run.fuzzy_epsilon = alternative.fuzzy_epsilon.value_or(options.fuzzy_epsilon);
  return run;
}

void validate(const FuzzySegmentOptions& options) {
  auto fail = [](const std::string& what) {
    throw InvalidInputException("segment_fuzzy: " + what);
  };
  if (options.parts < 0 || options.parts == 1)
    fail("parts must be 0 (automatic) or >= 2, got " + std::to_string(options.parts));
  if (options.max_parts < 2)
    fail("max_parts must be >= 2, got " + std::to_string(options.max_parts));
  if (options.max_depth < 1)
    fail("max_depth must be >= 1, got " + std::to_string(options.max_depth));
  if (!(options.angular_weight >= 0 && options.angular_weight <= 1))
    fail("angular_weight must be in [0, 1], got " + std::to_string(options.angular_weight));
  for (const FuzzyAlternative& alternative : options.alternatives) {
    FuzzySegmentOptions run = with_alternative(options, alternative);
    run.alternatives.clear();
    validate(run);
  }
  if (!(options.convex_eta > 0 && options.convex_eta <= 1))
    fail("convex_eta must be in (0, 1], got " + std::to_string(options.convex_eta));
  if (!(options.fuzzy_epsilon >= 0 && options.fuzzy_epsilon < 0.5))
    fail("fuzzy_epsilon must be in [0, 0.5), got " + std::to_string(options.fuzzy_epsilon));
  if (!(options.crease_angle_degrees >= 0 && options.crease_angle_degrees <= 180))
    fail("crease_angle_degrees must be in [0, 180], got " +
         std::to_string(options.crease_angle_degrees));
  if (!(options.min_area_fraction >= 0 && options.min_area_fraction < 1))
    fail("min_area_fraction must be in [0, 1), got " + std::to_string(options.min_area_fraction));
  if (!(options.neck_ratio > 0 && std::isfinite(options.neck_ratio)))
    fail("neck_ratio must be > 0, got " + std::to_string(options.neck_ratio));
  if (!(options.strip_tolerance >= 0 && std::isfinite(options.strip_tolerance)))
    fail("strip_tolerance must be >= 0, got " + std::to_string(options.strip_tolerance));
  if (!(options.straighten_width > 0 && std::isfinite(options.straighten_width)))
    fail("straighten_width must be > 0, got " + std::to_string(options.straighten_width));
}

}  // namespace

FuzzyAlternative parse_fuzzy_alternative(const std::string& text) {
  FuzzyAlternative alternative;
  std::istringstream words(text);
  std::string word;
  bool any = false;
  while (words >> word) {
    const std::size_t equals = word.find('=');
    const std::string key = word.substr(0, equals);
    double value = 0;
    std::size_t used = 0;
    try {
      if (equals != std::string::npos) value = std::stod(word.substr(equals + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (equals == std::string::npos || used == 0 || used != word.size() - equals - 1) {
      throw InvalidInputException("segment_fuzzy alternative '" + text +
                                  "': expected setting=number, got '" + word + "'");
    }
    if (key == "angular_weight") {
      alternative.angular_weight = value;
    } else if (key == "convex_eta") {
      alternative.convex_eta = value;
    } else if (key == "fuzzy_epsilon") {
      alternative.fuzzy_epsilon = value;
    } else {
      throw InvalidInputException("segment_fuzzy alternative '" + text + "': unknown setting '" +
                                  key + "' (angular_weight, convex_eta, fuzzy_epsilon)");
    }
    any = true;
  }
  if (!any) throw InvalidInputException("segment_fuzzy alternative: empty");
  return alternative;
}

std::string format_fuzzy_alternative(const FuzzyAlternative& alternative) {
  std::string text;
  auto setting = [&](const char* key, const std::optional<double>& value) {
    if (!value) return;
    std::ostringstream number;
    number << *value;
    text += (text.empty() ? "" : " ") + std::string(key) + "=" + number.str();
  };
  setting("angular_weight", alternative.angular_weight);
  setting("convex_eta", alternative.convex_eta);
  setting("fuzzy_epsilon", alternative.fuzzy_epsilon);
  return text;
}

std::vector<Mesh> segment_fuzzy(const Mesh& mesh, const FuzzySegmentOptions& options) {
  require_segmentable(mesh, "segment_fuzzy");
  validate(options);
  const FaceGraph graph = face_graph(mesh);
  const std::vector<int> component = face_components(graph);
  std::vector<std::vector<int>> components;
  for (std::size_t f = 0; f < component.size(); ++f) {
    if (component[f] >= static_cast<int>(components.size())) components.resize(component[f] + 1);
    components[component[f]].push_back(static_cast<int>(f));
  }
  EstimateCache estimates(options.strip_tolerance, options.refine, options.strip_limits);
  // One hierarchy's regions as face labels, and whether it split anything. On a connected
  // model, judged by strips, a decomposition costing more than `cap` is not looked for (the
  // hierarchy's branches are cut off as soon as they cost more).
  auto hierarchy_labels = [&](const FuzzySegmentOptions& run, int cap) {
    const Hierarchy hierarchy(mesh, graph, run, estimates);
    std::vector<int> labels(mesh.n_faces(), -1);
    int next_label = 0;
    for (const auto& faces : components) {
      std::vector<std::vector<int>> leaves =
          components.size() == 1 ? hierarchy.leaves(faces, 0, cap) : hierarchy.leaves(faces, 0);
      if (run.strip_tolerance > 0 && run.merge_neighbours && leaves.size() > 1)
        leaves = hierarchy.merge_cheaper_neighbours(std::move(leaves));
      for (const auto& leaf : leaves) {
        for (int f : leaf) labels[f] = next_label;
        ++next_label;
      }
    }
    labels = consolidate_regions(graph, labels, run.min_area_fraction * graph.total_area);
    return std::pair{std::move(labels), next_label > static_cast<int>(components.size())};
  };
  const double straighten_width = options.straighten_width * graph.mean_edge_length;
  constexpr int kUnbounded = std::numeric_limits<int>::max() / 2;
  if (options.strip_tolerance <= 0) {
    LabelledSoup surface = labelled_surface(mesh, hierarchy_labels(options, kUnbounded).first);
    if (options.straighten) straighten_boundaries(surface, {straighten_width});
    return build_pieces(surface);
  }
  // The regions were judged on meshes cut out one at a time and before straightening: judge
  // the parts as they will be emitted, straightened or not, against the model whole and
  // against the hierarchies of the alternative settings. Ties keep the model whole, then the
  // earlier settings, and the straightened parts over the others.
  const Hierarchy judge(mesh, graph, options, estimates);
  std::vector<int> component_labels = component;
  std::vector<Mesh> best = build_pieces(labelled_surface(mesh, component_labels));
  int best_cost = judge.strips_of(best, kUnbounded);
  std::vector<FuzzySegmentOptions> runs = {options};
  for (const FuzzyAlternative& alternative : options.alternatives)
    runs.push_back(with_alternative(options, alternative));
  for (const FuzzySegmentOptions& run : runs) {
    // Only a hierarchy that beats the best so far matters (as judged before straightening).
    auto [labels, split] = hierarchy_labels(run, best_cost - 1);
    if (!split) continue;
    LabelledSoup surface = labelled_surface(mesh, labels);
    std::vector<Mesh> parts = build_pieces(surface);
    int cost = judge.strips_of(parts, best_cost);
    if (options.straighten) {
      straighten_boundaries(surface, {straighten_width});
      std::vector<Mesh> straightened = build_pieces(surface);
      const int straightened_cost = judge.strips_of(straightened, std::min(cost, best_cost));
      if (straightened_cost <= cost) {
        parts = std::move(straightened);
        cost = straightened_cost;
      }
    }
    if (cost < best_cost) {
      best = std::move(parts);
      best_cost = cost;
    }
  }
  return best;
}

}  // namespace papercraft
