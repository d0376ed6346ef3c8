#pragma once
// Base64 (RFC 4648, with padding), for bytes embedded in text files: PNG images in the SVG
// pages, the 3D pieces in assembly.html.

#include <string>
#include <string_view>

namespace papercraft {

/// `bytes` in base64: A-Z, a-z, 0-9, + and /, padded with = to a multiple of four characters.
std::string base64(std::string_view bytes);

}  // namespace papercraft
