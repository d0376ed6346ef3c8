#pragma once
// Registry of node implementations by dotted name (`hausdorff.bounded`).

#include <map>
#include <string>
#include <vector>

#include "graph/node.h"

namespace papercraft {

class Registry {
 public:
  /// Adds an implementation. Throws std::logic_error on a duplicate name.
  void add(NodeSpec spec);
  /// nullptr if unknown.
  const NodeSpec* find(const std::string& name) const;
  std::vector<std::string> names() const;
  const std::map<std::string, NodeSpec>& specs() const { return specs_; }

 private:
  std::map<std::string, NodeSpec> specs_;
};

/// Every implementation shipped with papercraft (nodes/<stage>/<impl>_node.cpp).
void register_builtin_nodes(Registry& registry);

/// A registry with the builtin nodes (built once).
const Registry& builtin_registry();

}  // namespace papercraft
