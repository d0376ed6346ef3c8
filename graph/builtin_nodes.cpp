#include "graph/registry.h"

namespace papercraft {

// Defined in nodes/<stage>/<impl>_node.cpp.
void register_load_openmesh(Registry&);
void register_proxy_none(Registry&);
void register_proxy_decimate(Registry&);
void register_segment_none(Registry&);
void register_segment_feature(Registry&);
void register_segment_fuzzy(Registry&);
void register_select_nodes(Registry&);
void register_ruled_twist_dp(Registry&);
void register_hausdorff_bounded(Registry&);
void register_hausdorff_sampled(Registry&);
void register_cut_harmonic(Registry&);
void register_unfold_sequential(Registry&);
void register_merge_congruent(Registry&);
void register_layout_pages(Registry&);
void register_export_files(Registry&);

void register_builtin_nodes(Registry& registry) {
  register_load_openmesh(registry);
  register_proxy_none(registry);
  register_proxy_decimate(registry);
  register_segment_none(registry);
  register_segment_feature(registry);
  register_segment_fuzzy(registry);
  register_select_nodes(registry);
  register_ruled_twist_dp(registry);
  register_hausdorff_bounded(registry);
  register_hausdorff_sampled(registry);
  register_cut_harmonic(registry);
  register_unfold_sequential(registry);
  register_merge_congruent(registry);
  register_layout_pages(registry);
  register_export_files(registry);
}

const Registry& builtin_registry() {
  static const Registry registry = [] {
    Registry r;
    register_builtin_nodes(r);
    return r;
  }();
  return registry;
}

}  // namespace papercraft
