// Fuzz target: the bytes as a mesh file of one format (PAPERCRAFT_FUZZ_EXTENSION: ".obj",
// ".off", ".ply" or ".stl"; ascii and binary alike) through the whole loader and its
// validation. Refusing the file (InvalidInputException, IOException) is the expected outcome;
// anything else escaping, a crash, a sanitizer report or a timeout is a finding.

#include <cstddef>
#include <cstdint>

#include "core/errors.h"
#include "fuzz/fuzz_input.h"
#include "nodes/load/openmesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace papercraft;
  fuzz::silence_logs();
  const auto path = fuzz::write_scratch_file("input" PAPERCRAFT_FUZZ_EXTENSION, data, size);
  try {
    const LoadedMesh loaded = load_mesh(path);
    (void)loaded;
  } catch (const InvalidInputException&) {
  } catch (const IOException&) {
  }
  return 0;
}
