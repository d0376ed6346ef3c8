// Fuzz target: the bytes as a pipeline config (YAML), checked as `papercraft validate` does:
// parsed against the builtin registry, the graph built, every node created from its
// parameters. A usage error (ConfigException, InvalidInputException, IOException: exit 2) is
// the expected refusal; anything else escaping is an internal error and a finding.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "fuzz/fuzz_input.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace papercraft;
  fuzz::silence_logs();
  const std::string text(reinterpret_cast<const char*>(data), size);
  const Registry& registry = builtin_registry();
  try {
    const PipelineConfig config = parse_pipeline_config(text, "fuzz.yaml", registry);
    const Pipeline pipeline(config, registry);
    const NodeContext context{pipeline.refine_options()};
    for (const auto& node : config.nodes) registry.find(node.impl)->create(node.params, context);
  } catch (const ConfigException&) {
  } catch (const InvalidInputException&) {
  } catch (const IOException&) {
  }
  return 0;
}
