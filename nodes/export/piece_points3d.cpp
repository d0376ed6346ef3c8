#include "nodes/export/piece_points3d.h"

#include <string>

#include "core/errors.h"

namespace papercraft {

std::vector<Vec3> piece_points3d(const PlacedPiece& piece, const FlatStrip& strip) {
  if (piece.points3d.size() == piece.vertices.size()) return piece.points3d;
  std::vector<Vec3> points;
  points.reserve(piece.vertices.size());
  for (std::size_t i = 0; i < piece.vertices.size(); ++i) {
    const int v = i < piece.strip_vertex.size() ? piece.strip_vertex[i] : -1;
    if (v < 0 || v >= static_cast<int>(strip.vertices3d.size()))
      throw InvalidInputException("piece " + piece.name + ": vertex " + std::to_string(i) +
                                  " has no point on strip " + std::to_string(strip.id));
    points.push_back(strip.vertices3d[v]);
  }
  return points;
}

}  // namespace papercraft
