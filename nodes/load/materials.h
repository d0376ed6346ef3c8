#pragma once
// Materials of an OBJ's .mtl library: which texture image each material names, so that a
// missing image can be reported with the material that wanted it.

#include <filesystem>
#include <map>
#include <string>

namespace papercraft::load_internal {

/// The diffuse texture file (map_Kd, options stripped) -> the name of the first material that
/// uses it (newmtl). Empty when the library cannot be read; never throws.
std::map<std::string, std::string> material_names(const std::filesystem::path& library);

/// A map_Kd value without its options ("-s 1 1 1 wood.png" -> "wood.png").
std::string texture_file_name(const std::string& map_kd);

}  // namespace papercraft::load_internal
