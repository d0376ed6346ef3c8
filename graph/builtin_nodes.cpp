#include "graph/registry.h"

namespace papercraft {

// One line per implementation (nodes/<stage>/<impl>_node.cpp).
void register_builtin_nodes(Registry& registry) {
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
