// Fuzz target: the bytes as a mesh given in memory (the Python module's arrays) through
// load_arrays and the loader's validation and repairs. The first byte is the vertex count
// (0..255, fewer where the bytes run out), then three doubles per vertex, then the rest as
// triangles of three 32-bit indices (any value: negative, out of range, repeated). Refusing the
// mesh (InvalidInputException) is the expected outcome; anything else escaping, a crash, a
// sanitizer report or a timeout is a finding.

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "core/errors.h"
#include "fuzz/fuzz_input.h"
#include "nodes/load/openmesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace papercraft;
  fuzz::silence_logs();
  if (size == 0) return 0;
  std::size_t at = 1;
  TriangleMesh mesh;
  for (int v = 0; v < data[0] && at + 3 * sizeof(double) <= size; ++v) {
    double xyz[3];
    std::memcpy(xyz, data + at, sizeof xyz);
    at += sizeof xyz;
    mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  while (at + 3 * sizeof(std::int32_t) <= size) {
    std::int32_t t[3];
    std::memcpy(t, data + at, sizeof t);
    at += sizeof t;
    mesh.triangles.push_back({t[0], t[1], t[2]});
  }
  try {
    const LoadedMesh loaded = load_arrays(mesh, "<arrays>");
    (void)loaded;
  } catch (const InvalidInputException&) {
  }
  return 0;
}
