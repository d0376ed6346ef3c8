#include "nodes/export/image.h"

#include <cairo.h>
#include <jpeglib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include "core/errors.h"

namespace papercraft {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw IOException(path.string() + ": " + why);
}

void check_size(const std::filesystem::path& path, long width, long height, long max_pixels) {
  if (width <= 0 || height <= 0) fail(path, "the image has no pixels");
  if (width * height > max_pixels)
    fail(path, "the image is " + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels, more than max_texture_pixels (" + std::to_string(max_pixels) +
                   "): not read");
}

// The IHDR chunk follows the 8-byte signature: width and height, big-endian, at 16 and 20.
void check_png_header(const std::filesystem::path& path, const unsigned char* header,
                      long max_pixels) {
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!std::equal(header, header + 8, kSignature)) fail(path, "not a PNG file");
  auto be32 = [&](int at) {
    return (long(header[at]) << 24) | (long(header[at + 1]) << 16) | (long(header[at + 2]) << 8) |
           long(header[at + 3]);
  };
  check_size(path, be32(16), be32(20), max_pixels);
}

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

Image image_of_surface(const std::filesystem::path& path, const SurfacePtr& surface) {
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    fail(path, std::string("cannot decode the PNG: ") +
                   cairo_status_to_string(cairo_surface_status(surface.get())));
  cairo_surface_flush(surface.get());
  Image image;
  image.width = cairo_image_surface_get_width(surface.get());
  image.height = cairo_image_surface_get_height(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const cairo_format_t format = cairo_image_surface_get_format(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  image.rgb.resize(std::size_t(image.width) * image.height * 3);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* out = &image.rgb[(std::size_t(y) * image.width + x) * 3];
      if (format == CAIRO_FORMAT_ARGB32 || format == CAIRO_FORMAT_RGB24) {
        std::uint32_t pixel;
        std::memcpy(&pixel, data + std::size_t(y) * stride + 4 * x, 4);
        const unsigned a = format == CAIRO_FORMAT_ARGB32 ? (pixel >> 24) & 0xff : 255;
        // Premultiplied alpha: un-premultiply; a transparent pixel prints as white paper.
        for (int c = 0; c < 3; ++c) {
          const unsigned value = (pixel >> (16 - 8 * c)) & 0xff;
          out[c] =
              a == 0 ? 255 : static_cast<std::uint8_t>(std::min(255u, value * 255 / a + (255 - a)));
        }
      } else {  // A8, A1: a mask
        const unsigned char value =
            format == CAIRO_FORMAT_A8 ? data[std::size_t(y) * stride + x] : 0;
        out[0] = out[1] = out[2] = static_cast<std::uint8_t>(255 - value);
      }
    }
  }
  return image;
}

// cairo's PNG stream reader over bytes in memory.
struct MemoryReader {
  const std::vector<std::uint8_t>* bytes;
  std::size_t at = 0;
};

cairo_status_t read_from_memory(void* closure, unsigned char* data, unsigned int length) {
  auto* reader = static_cast<MemoryReader*>(closure);
  if (reader->bytes->size() - reader->at < length) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, reader->bytes->data() + reader->at, length);
  reader->at += length;
  return CAIRO_STATUS_SUCCESS;
}

Image decode_png(const std::filesystem::path& name, const std::vector<std::uint8_t>& bytes,
                 long max_pixels) {
  if (bytes.size() < 24) fail(name, "cannot read the PNG header");
  check_png_header(name, bytes.data(), max_pixels);
  MemoryReader reader{&bytes};
  const SurfacePtr surface(cairo_image_surface_create_from_png_stream(&read_from_memory, &reader),
                           &cairo_surface_destroy);
  return image_of_surface(name, surface);
}

struct JpegError {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void on_jpeg_error(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->message);
  std::longjmp(error->jump, 1);
}

Image decode_jpeg(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                  long max_pixels) {
  jpeg_decompress_struct info;
  JpegError error;
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = on_jpeg_error;
  Image image;
  std::string failure;
  long too_large_width = 0, too_large_height = 0;
  if (setjmp(error.jump)) {
    jpeg_destroy_decompress(&info);
    fail(path, std::string("cannot decode the JPEG: ") + error.message);
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  if (long(info.image_width) * long(info.image_height) > max_pixels) {
    too_large_width = info.image_width;
    too_large_height = info.image_height;
    jpeg_destroy_decompress(&info);
    check_size(path, too_large_width, too_large_height, max_pixels);
  }
  info.out_color_space = JCS_RGB;
  jpeg_start_decompress(&info);
  image.width = static_cast<int>(info.output_width);
  image.height = static_cast<int>(info.output_height);
  image.rgb.resize(std::size_t(image.width) * image.height * 3);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = &image.rgb[std::size_t(info.output_scanline) * image.width * 3];
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return image;
}

}  // namespace

Vec3 Image::sample(const Vec2& uv) const {
  if (width <= 0 || height <= 0) return Vec3::Constant(1.0);
  const double u = uv.x() - std::floor(uv.x()), v = uv.y() - std::floor(uv.y());
  const double x = u * width - 0.5, y = (1.0 - v) * height - 0.5;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  const double weight[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  double channel[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const int px = (((x0 + (k & 1)) % width) + width) % width;
    const int py = std::clamp(y0 + (k >> 1), 0, height - 1);
    const std::uint8_t* p = &rgb[(std::size_t(py) * width + px) * 3];
    for (int c = 0; c < 3; ++c) channel[c] += weight[k] * p[c];
  }
  return Vec3(channel[0], channel[1], channel[2]) / 255.0;
}

std::string png_bytes(cairo_surface_t* surface) {
  std::string bytes;
  const cairo_status_t status = cairo_surface_write_to_png_stream(
      surface,
      [](void* closure, const unsigned char* chunk, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(chunk), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &bytes);
  if (status != CAIRO_STATUS_SUCCESS) bytes.clear();
  return bytes;
}

Image load_image(const std::filesystem::path& path, long max_pixels) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool png = extension == ".png";
  if (!png && extension != ".jpg" && extension != ".jpeg")
    fail(path, "unsupported image format " + extension + " (PNG and JPEG are read)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  return png ? decode_png(path, bytes, max_pixels) : decode_jpeg(path, bytes, max_pixels);
}

Image decode_image(const std::string& name, const std::vector<std::uint8_t>& bytes,
                   long max_pixels) {
  if (bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' &&
      bytes[3] == 'G')
    return decode_png(name, bytes, max_pixels);
  if (bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff)
    return decode_jpeg(name, bytes, max_pixels);
  fail(name, "unsupported image format (PNG and JPEG are read)");
}

}  // namespace papercraft
