#include "fuzz/fuzz_input.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <OpenMesh/Core/System/omstream.hh>
#include <cstdlib>
#include <fstream>

namespace papercraft::fuzz {

const std::filesystem::path& scratch_dir() {
  // Never destroyed: the exit handler that removes the folder runs after the destructor of a
  // static constructed around its registration.
  static const std::filesystem::path* const dir = [] {
    const auto* path = new std::filesystem::path(std::filesystem::temp_directory_path() /
                                                 ("papercraft-fuzz-" + std::to_string(::getpid())));
    std::filesystem::create_directories(*path);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_dir(), ignored);
    });
    return path;
  }();
  return *dir;
}

std::filesystem::path write_scratch_file(const std::string& name, const std::uint8_t* data,
                                         std::size_t size) {
  const auto path = scratch_dir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

void silence_logs() {
  static const bool once = [] {
    spdlog::set_level(spdlog::level::off);
    omlog().disable();
    omout().disable();
    omerr().disable();
    return true;
  }();
  (void)once;
}

}  // namespace papercraft::fuzz
