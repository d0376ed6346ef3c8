#pragma once
// Texture images for the print: PNG through cairo, JPEG through libjpeg(-turbo). The size is
// read from the file's header first, so an image too large to be worth reading is refused
// before any pixel is decoded.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"

typedef struct _cairo_surface cairo_surface_t;

namespace papercraft {

/// 8-bit RGB pixels, row by row from the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  /// Bilinear sample at texture coordinates (u, v) in [0, 1] (v up, wrapping around as OBJ
  /// textures repeat); linear 0..1 RGB.
  Vec3 sample(const Vec2& uv) const;
};

/// Reads a .png or .jpg/.jpeg image.
/// \throws IOException naming the file when it is missing, unreadable, of another format, or
///   larger than max_pixels (width * height).
Image load_image(const std::filesystem::path& path, long max_pixels);

/// Decodes a PNG or JPEG held in memory (told apart by their signatures); `name` is what
/// messages call it (e.g. "cube.glb#image0.png").
/// \throws IOException naming `name` as load_image does.
Image decode_image(const std::string& name, const std::vector<std::uint8_t>& bytes,
                   long max_pixels);

/// A cairo image surface encoded as PNG: the file's bytes (empty if cairo fails).
std::string png_bytes(cairo_surface_t* surface);

}  // namespace papercraft
