// Reading an OBJ's .mtl library for the names of its materials.
#include "nodes/load/materials.h"

#include <fstream>

#include "nodes/load/parse_values.h"

namespace papercraft::load_internal {

std::string texture_file_name(const std::string& map_kd) {
  std::string_view name = trim(map_kd);
  if (!name.empty() && name.front() == '-') {
    // map_Kd options ("-s 1 1 1 wood.png"): the file name comes last.
    const std::size_t last = name.find_last_of(" \t");
    if (last != std::string_view::npos) name = name.substr(last + 1);
  }
  return std::string(name);
}

std::map<std::string, std::string> material_names(const std::filesystem::path& library) {
  std::map<std::string, std::string> names;
  std::ifstream in(library, std::ios::binary);
  std::string line, current;
  // A library is small; a broken one (binary junk, huge lines) only loses the names.
  for (int lines = 0; lines < 1'000'000 && std::getline(in, line); ++lines) {
    if (line.size() > 4096) continue;
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword == "newmtl") {
      current = std::string(trim(rest));
    } else if (keyword == "map_Kd" && !current.empty()) {
      names.emplace(texture_file_name(std::string(trim(rest))), current);
    }
  }
  return names;
}

}  // namespace papercraft::load_internal
