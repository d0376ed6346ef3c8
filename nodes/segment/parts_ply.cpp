#include "nodes/segment/parts_ply.h"

#include <cmath>
#include <sstream>

namespace papercraft {

std::array<unsigned char, 3> part_colour(int index) {
  const double golden = 0.6180339887498949;
  const double hue = std::fmod(0.1 + index * golden, 1.0) * 6.0;
  // HSV with saturation 0.65 and value 0.95.
  const double v = 0.95, s = 0.65;
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r = v, g = t, b = p;
  switch (sector) {
    case 1: r = q, g = v, b = p; break;
    case 2: r = p, g = v, b = t; break;
    case 3: r = p, g = q, b = v; break;
    case 4: r = t, g = p, b = v; break;
    case 5: r = v, g = p, b = q; break;
    default: break;
  }
  auto byte = [](double x) { return static_cast<unsigned char>(std::lround(255 * x)); };
  return {byte(r), byte(g), byte(b)};
}

std::string parts_ply(const std::vector<Mesh>& parts) {
  std::size_t vertices = 0, faces = 0;
  for (const Mesh& part : parts) {
    vertices += part.n_vertices();
    faces += part.n_faces();
  }
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\ncomment papercraft segmentation: faces coloured by part\n"
      << "element vertex " << vertices << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << faces << "\nproperty list uchar int vertex_indices\n"
      << "property int part\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "end_header\n";
  out.precision(17);
  for (const Mesh& part : parts) {
    for (auto v : part.vertices()) {
      const auto& p = part.point(v);
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
  }
  std::size_t base = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto colour = part_colour(static_cast<int>(i));
    for (auto f : parts[i].faces()) {
      out << 3;
      for (auto v : f.vertices()) out << ' ' << base + v.idx();
      out << ' ' << i << ' ' << int{colour[0]} << ' ' << int{colour[1]} << ' ' << int{colour[2]}
          << '\n';
    }
    base += parts[i].n_vertices();
  }
  return out.str();
}

}  // namespace papercraft
