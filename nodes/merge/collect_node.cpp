// Adapter support shared by merge.congruent and merge.none (see collect_node.h).

#include "nodes/merge/collect_node.h"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/seams.h"

namespace papercraft {

namespace {

// "0.10.2" -> {0, 10, 2}
std::vector<int> path_key(const std::string& path) {
  std::vector<int> key;
  std::size_t start = 0;
  while (start <= path.size()) {
    std::size_t dot = path.find('.', start);
    if (dot == std::string::npos) dot = path.size();
    key.push_back(std::stoi(path.substr(start, dot - start)));
    start = dot + 1;
  }
  return key;
}

}  // namespace

ModelStrips collect_model_strips(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded) {
  std::sort(unfolded.begin(), unfolded.end(), [](const auto& a, const auto& b) {
    return path_key(a->strip->candidate->part.path) < path_key(b->strip->candidate->part.path);
  });
  ModelStrips strips;
  for (const auto& u : unfolded) {
    const int source = static_cast<int>(strips.strips3d.size());
    spdlog::debug("strip {}: part {} ({} faces, area {:.4g}), {} flat", source,
                  u->strip->candidate->part.path, u->strip->candidate->part.mesh->n_faces(),
                  surface_area(*u->strip->candidate->part.mesh), u->flat.size());
    strips.strips3d.push_back(u->strip);
    if (!strips.model) strips.model = u->strip->candidate->part.model;
    for (FlatStrip flat : u->flat) {
      flat.id = static_cast<int>(strips.flat.size());
      flat.source_strip = source;
      strips.flat.push_back(std::move(flat));
    }
  }
  strips.flat_before_merge = strips.flat.size();
  split_t_junctions(strips.flat);
  label_seams(strips.flat);
  return strips;
}

void record_model_strips(ModelRun& model, const ModelStrips& strips) {
  double bound = 0.0;
  bool certified = true;
  for (const auto& s : strips.strips3d) {
    bound = std::max(bound, s->upper_bound);
    certified = certified && s->certified;
  }
  // H(strips, input) <= H(strips, proxy) + H(proxy, input); without a proxy the second is 0.
  const double proxy_distance = model.proxy_distance();
  model.update([&](ModelRecord& r) {
    r.strips_3d = static_cast<int>(strips.strips3d.size());
    r.flat_strips_before_merge = static_cast<int>(strips.flat_before_merge);
    r.flat_strips = static_cast<int>(strips.flat.size());
    r.strips_bound = bound;
    r.hausdorff_bound = bound + proxy_distance;
    r.certified = certified;
  });
}

}  // namespace papercraft
