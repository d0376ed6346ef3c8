// Fuzz target: the bytes as a batch job file (YAML: inputs, output, config, tolerance, ...),
// read and checked as `papercraft batch` does before any model runs. A ConfigException or
// IOException (exit 2) is the expected refusal; anything else escaping is a finding.

#include <cstddef>
#include <cstdint>

#include "core/errors.h"
#include "fuzz/fuzz_input.h"
#include "runner/batch_job.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace papercraft;
  fuzz::silence_logs();
  const auto path = fuzz::write_scratch_file("job.yaml", data, size);
  try {
    const BatchJob job = load_batch_job(path);
    (void)job;
  } catch (const ConfigException&) {
  } catch (const InvalidInputException&) {
  } catch (const IOException&) {
  }
  return 0;
}
