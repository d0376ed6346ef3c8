#include "graph/registry.h"

#include <stdexcept>

namespace papercraft {

void Registry::add(NodeSpec spec) {
  const std::string name = spec.name;
  if (!specs_.emplace(name, std::move(spec)).second) {
    throw std::logic_error("node implementation '" + name + "' registered twice");
  }
}

const NodeSpec* Registry::find(const std::string& name) const {
  auto it = specs_.find(name);
  return it == specs_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::names() const {
  std::vector<std::string> out;
  for (const auto& [name, spec] : specs_) out.push_back(name);
  return out;
}

}  // namespace papercraft
