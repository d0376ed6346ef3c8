// Fuzz target: the bytes as an OBJ's material library (.mtl), read on its own and through the
// loader with an OBJ that names it (mtllib, usemtl). The reader never throws; the loader may
// refuse the OBJ only for what is wrong with the OBJ, which here is nothing.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "fuzz/fuzz_input.h"
#include "nodes/load/materials.h"
#include "nodes/load/openmesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace papercraft;
  fuzz::silence_logs();
  const auto library = fuzz::write_scratch_file("materials.mtl", data, size);
  for (const auto& [texture, material] : load_internal::material_names(library)) {
    (void)load_internal::texture_file_name(texture);
    (void)material;
  }
  static const std::string obj =
      "mtllib materials.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\n"
      "vt 0 1\nf 1/1 3/3 2/2\nusemtl b\nf 1/1 2/2 4/3\nf 2/2 3/3 4/1\nf 3/3 1/1 4/2\n";
  const auto mesh = fuzz::write_scratch_file(
      "with_materials.obj", reinterpret_cast<const std::uint8_t*>(obj.data()), obj.size());
  const LoadedMesh loaded = load_mesh(mesh);
  (void)loaded;
  return 0;
}
