#include "nodes/export/bake.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <vector>

#include "core/closest_point.h"

namespace papercraft {
namespace {

std::uint32_t argb(const Vec3& rgb) {
  auto channel = [](double c) {
    return static_cast<std::uint32_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
  };
  return 0xff000000u | (channel(rgb.x()) << 16) | (channel(rgb.y()) << 8) | channel(rgb.z());
}

// Pixels are sampled in square tiles: the nearest triangle of every point of a tile is among
// the few triangles near the tile's centre (SurfaceSampler::nearest_candidates), so one
// tree search serves the whole tile; a tile with too many candidates searches per pixel.
constexpr int kTile = 8;
constexpr std::size_t kTileCandidates = 32;

// Fills the pixels of `image` whose centres lie in the triangle `corners` (page mm, either
// orientation) with the surface colour nearest `point(weights)`.
template <class Point>
void fill_triangle(BakedImage& image, const std::array<Vec2, 3>& corners, Point point,
                   const SurfaceSampler& sampler, int* hint,
                   const std::vector<Vec2>* clip = nullptr) {
  const Vec2 a = corners[0], b = corners[1], c = corners[2];
  const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  if (std::abs(area) < 1e-18) return;
  Vec2 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
  if (clip) {
    lo = Vec2::Constant(1e300), hi = -lo;
    for (const Vec2& q : *clip) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  }
  const int x0 =
      std::max(0, static_cast<int>(std::floor((lo.x() - image.origin.x()) / image.pixel_mm)));
  const int x1 = std::min(
      image.width - 1, static_cast<int>(std::floor((hi.x() - image.origin.x()) / image.pixel_mm)));
  const int y0 =
      std::max(0, static_cast<int>(std::floor((lo.y() - image.origin.y()) / image.pixel_mm)));
  const int y1 = std::min(
      image.height - 1, static_cast<int>(std::floor((hi.y() - image.origin.y()) / image.pixel_mm)));
  auto inside_clip = [&](const Vec2& p) {
    bool inside = false;
    for (std::size_t i = 0, j = clip->size() - 1; i < clip->size(); j = i++) {
      const Vec2 &u = (*clip)[i], &v = (*clip)[j];
      if ((u.y() > p.y()) != (v.y() > p.y()) &&
          p.x() < (v.x() - u.x()) * (p.y() - u.y()) / (v.y() - u.y()) + u.x())
        inside = !inside;
    }
    return inside;
  };
  struct Sample {
    std::uint32_t* pixel;
    Vec3 point;
  };
  std::vector<Sample> tile;
  std::vector<SurfaceSampler::Candidate> candidates;
  // The columns of row y that can hold the triangle's pixels (a pixel either side of the exact
  // span, so the per-pixel test below decides): each barycentric weight is linear along a row.
  auto row_span = [&](int y) -> std::pair<int, int> {
    if (clip) return {x0, x1};
    const double py = image.origin.y() + (y + 0.5) * image.pixel_mm;
    double lo_x = -1e300, hi_x = 1e300;
    // weight(px) = slope * px + offset for wb, wc and wa = 1 - wb - wc.
    const double sb = (c - a).y() / area,
                 ob = (-a.x() * (c - a).y() - (py - a.y()) * (c - a).x()) / area;
    const double sc = -(b - a).y() / area,
                 oc = ((b - a).x() * (py - a.y()) + a.x() * (b - a).y()) / area;
    const double slopes[3] = {sb, sc, -sb - sc}, offsets[3] = {ob, oc, 1 - ob - oc};
    for (int k = 0; k < 3; ++k) {
      if (slopes[k] > 0)
        lo_x = std::max(lo_x, -offsets[k] / slopes[k]);
      else if (slopes[k] < 0)
        hi_x = std::min(hi_x, -offsets[k] / slopes[k]);
      else if (offsets[k] < -1e-9)
        return {1, 0};
    }
    if (lo_x > hi_x) return {1, 0};
    const double first = (lo_x - image.origin.x()) / image.pixel_mm - 0.5;
    const double last = (hi_x - image.origin.x()) / image.pixel_mm - 0.5;
    return {std::max(x0, static_cast<int>(std::max(-1e9, std::floor(first))) - 1),
            std::min(x1, static_cast<int>(std::min(1e9, std::ceil(last))) + 1)};
  };
  std::array<std::pair<int, int>, kTile> spans;
  for (int ty = y0; ty <= y1; ty += kTile) {
    const int rows = std::min(y1, ty + kTile - 1) - ty + 1;
    int from = x1 + 1, to = x0 - 1;
    for (int r = 0; r < rows; ++r) {
      spans[r] = row_span(ty + r);
      if (spans[r].first <= spans[r].second)
        from = std::min(from, spans[r].first), to = std::max(to, spans[r].second);
    }
    for (int tx = from; tx <= to; tx += kTile) {
      tile.clear();
      for (int y = ty; y < ty + rows; ++y) {
        const auto [first, last] = spans[y - ty];
        for (int x = std::max(tx, first); x <= std::min(last, tx + kTile - 1); ++x) {
          std::uint32_t& pixel = image.argb[std::size_t(y) * image.width + x];
          if (pixel != 0) continue;
          const Vec2 p =
              image.origin + Vec2((x + 0.5) * image.pixel_mm, (y + 0.5) * image.pixel_mm);
          // Barycentric weights; outside the triangle only for a clipped tab (extrapolated).
          const double wb = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / area;
          const double wc = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
          const double wa = 1 - wb - wc;
          if (clip ? !inside_clip(p) : (wa < -1e-9 || wb < -1e-9 || wc < -1e-9)) continue;
          tile.push_back({&pixel, point(wa, wb, wc)});
        }
      }
      if (tile.empty()) continue;
      Vec3 rgb;
      bool shared = false;
      Vec3 centre = Vec3::Zero();
      if (tile.size() > 2) {
        for (const Sample& sample : tile) centre += sample.point;
        centre /= static_cast<double>(tile.size());
        double radius = 0;
        for (const Sample& sample : tile) radius = std::max(radius, (sample.point - centre).norm());
        shared = sampler.nearest_candidates(centre, radius, kTileCandidates, candidates);
      }
      for (const Sample& sample : tile) {
        const bool found = shared ? sampler.colour_among(sample.point, centre, candidates, &rgb)
                                  : sampler.colour(sample.point, hint, &rgb);
        if (found) *sample.pixel = argb(rgb);
      }
    }
  }
}

// Grows the painted area by `rings` pixels, each new pixel taking a painted neighbour's colour
// (the first of left, right, up, down, then the diagonals, painted before its ring). Only the
// pixels along the edge of the painted area are visited.
void bleed(BakedImage& image, int rings) {
  static constexpr int dx[8] = {-1, 1, 0, 0, -1, 1, -1, 1};
  static constexpr int dy[8] = {0, 0, -1, 1, -1, -1, 1, 1};
  const int w = image.width, h = image.height;
  auto at = [&](int x, int y) -> std::uint32_t& { return image.argb[std::size_t(y) * w + x]; };
  // The unpainted neighbours of the pixels painted last, each once.
  std::vector<char> queued(image.argb.size(), 0);
  std::vector<std::pair<int, int>> frontier;
  auto queue_neighbours = [&](int x, int y) {
    for (int k = 0; k < 8; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h || at(nx, ny) != 0) continue;
      char& mark = queued[std::size_t(ny) * w + nx];
      if (!mark) mark = 1, frontier.push_back({nx, ny});
    }
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (at(x, y) != 0) queue_neighbours(x, y);
  std::vector<std::pair<std::uint32_t*, std::uint32_t>> painted;
  for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
    painted.clear();
    for (const auto& [x, y] : frontier) {
      for (int k = 0; k < 8; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        if (const std::uint32_t value = at(nx, ny); value != 0) {
          painted.push_back({&at(x, y), value});
          break;
        }
      }
    }
    for (const auto& [pixel, value] : painted) *pixel = value;
    std::vector<std::pair<int, int>> last;
    last.swap(frontier);
    for (const auto& [x, y] : last) queue_neighbours(x, y);
  }
}

}  // namespace

SurfaceSampler::SurfaceSampler(const Mesh& input, const SurfaceAppearance& appearance,
                               std::vector<std::shared_ptr<const Image>> images)
    : bvh_(to_triangle_mesh(input)), images_(std::move(images)) {
  const auto& triangles = bvh_.mesh().triangles;
  const std::size_t faces = triangles.size();
  const bool textured =
      appearance.face_uv.size() == faces && appearance.face_material.size() == faces;
  const bool coloured = appearance.face_colour.size() == faces;
  if (appearance.face_vertices.size() != faces || (!textured && !coloured)) return;
  material_.assign(faces, -1);
  if (textured) uv_.resize(faces);
  if (coloured) colour_.resize(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    for (int i = 0; i < 3; ++i) {
      // The appearance's corner at this triangle's i-th vertex.
      int k = 0;
      while (k < 2 && appearance.face_vertices[f][k] != triangles[f][i]) ++k;
      if (textured) uv_[f][i] = appearance.face_uv[f][k];
      if (coloured) colour_[f][i] = appearance.face_colour[f][k];
    }
    if (textured) material_[f] = appearance.face_material[f];
  }
  bool any_image = false;
  for (const auto& image : images_) any_image = any_image || image != nullptr;
  empty_ = !coloured && !(textured && any_image);
}

bool SurfaceSampler::colour(const Vec3& p, int* hint, Vec3* rgb) const {
  if (empty_) return false;
  const BvhClosestHit hit =
      *hint >= 0 ? bvh_.closest(p, std::span<const int>(hint, 1)) : bvh_.closest(p);
  if (!hit.found()) return false;
  *hint = hit.triangle;
  return shade(hit.triangle, hit.barycentric, rgb);
}

bool SurfaceSampler::nearest_candidates(const Vec3& centre, double radius, std::size_t limit,
                                        std::vector<Candidate>& out) const {
  out.clear();
  const BvhClosestHit hit = bvh_.closest(centre);
  if (!hit.found()) return false;
  const double reach = hit.distance + 2 * radius;
  Aabb box;
  box.extend(centre - Vec3::Constant(reach));
  box.extend(centre + Vec3::Constant(reach));
  thread_local std::vector<int> meeting;  // reused: one search per tile
  meeting.clear();
  if (!bvh_.triangles_meeting(box, meeting, 4 * limit)) return false;
  for (const int t : meeting) {
    const double d = std::sqrt(bvh_.squared_distance_to_triangle(centre, t));
    if (d <= reach) out.push_back({d, t});
  }
  if (out.size() > limit) return false;
  std::sort(out.begin(), out.end(), [](const Candidate& x, const Candidate& y) {
    return x.distance < y.distance || (x.distance == y.distance && x.triangle < y.triangle);
  });
  return true;
}

bool SurfaceSampler::colour_among(const Vec3& p, const Vec3& centre,
                                  std::span<const Candidate> candidates, Vec3* rgb) const {
  if (empty_ || candidates.empty()) return false;
  const TriangleMesh& mesh = bvh_.mesh();
  const double offset = (p - centre).norm();
  double best_squared = std::numeric_limits<double>::infinity();
  int best = -1;
  Vec3 weights = Vec3::Zero();
  for (const Candidate& candidate : candidates) {
    // d(p, t) >= d(centre, t) - |p - centre|: the rest are farther than the best.
    const double lower = candidate.distance - offset;
    if (lower > 0 && lower * lower > best_squared * (1 + 1e-9)) break;
    const int t = candidate.triangle;
    const Triangle& tri = mesh.triangles[t];
    const TriangleClosestPoint c = closest_point_on_triangle(
        p, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
    if (c.squared_distance < best_squared || (c.squared_distance == best_squared && t < best)) {
      best_squared = c.squared_distance;
      best = t;
      weights = c.barycentric;
    }
  }
  return shade(best, weights, rgb);
}

bool SurfaceSampler::shade(int t, const Vec3& w, Vec3* rgb) const {
  if (!uv_.empty() && material_[t] >= 0 &&
      static_cast<std::size_t>(material_[t]) < images_.size() && images_[material_[t]]) {
    const Vec2 uv = w.x() * uv_[t][0] + w.y() * uv_[t][1] + w.z() * uv_[t][2];
    *rgb = images_[material_[t]]->sample(uv);
    return true;
  }
  if (!colour_.empty()) {
    *rgb = w.x() * colour_[t][0] + w.y() * colour_[t][1] + w.z() * colour_[t][2];
    return true;
  }
  return false;
}

std::vector<BakedImage> bake_page(const Page& page, const std::map<int, const FlatStrip*>& strips,
                                  const SurfaceSampler& sampler, const BakeOptions& options) {
  std::vector<BakedImage> images;
  const double pixel = 25.4 / options.dpi;
  const int rings = static_cast<int>(std::ceil(options.bleed_mm / pixel));
  for (const PlacedPiece& piece : page.pieces) {
    BakedImage image;
    const auto found = strips.find(piece.strip_id);
    if (found == strips.end() || sampler.empty() || piece.triangles.empty()) {
      images.push_back(std::move(image));
      continue;
    }
    const FlatStrip& strip = *found->second;
    Vec2 lo = Vec2::Constant(1e300), hi = -lo;
    for (const Vec2& v : piece.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (const Tab& tab : piece.tabs)
      for (const auto& flap : tab.flaps)
        for (const Vec2& v : flap) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    image.pixel_mm = pixel;
    image.origin = lo - Vec2::Constant((rings + 1) * pixel);
    image.width = static_cast<int>(std::ceil((hi.x() - image.origin.x()) / pixel)) + rings + 1;
    image.height = static_cast<int>(std::ceil((hi.y() - image.origin.y()) / pixel)) + rings + 1;
    image.argb.assign(std::size_t(image.width) * image.height, 0);
    int hint = -1;
    for (const Triangle& t : piece.triangles) {
      const std::array<Vec2, 3> corners{piece.vertices[t[0]], piece.vertices[t[1]],
                                        piece.vertices[t[2]]};
      // points3d: every vertex's point (where a layout added points, no strip vertex has it).
      const bool own = piece.points3d.size() == piece.vertices.size();
      auto point = [&](int v) -> const Vec3& {
        return own ? piece.points3d[v] : strip.vertices3d[piece.strip_vertex[v]];
      };
      const Vec3 &pa = point(t[0]), &pb = point(t[1]), &pc = point(t[2]);
      fill_triangle(
          image, corners,
          [&](double wa, double wb, double wc) { return Vec3(wa * pa + wb * pb + wc * pc); },
          sampler, &hint);
    }
    if (options.tab_texture) {
      for (const Tab& tab : piece.tabs)
        for (const TexturePatch& patch : tab.texture) {
          if (patch.clip.size() < 3) continue;
          fill_triangle(
              image, patch.corners,
              [&](double wa, double wb, double wc) {
                return Vec3(wa * patch.points3d[0] + wb * patch.points3d[1] +
                            wc * patch.points3d[2]);
              },
              sampler, &hint, &patch.clip);
        }
    }
    bleed(image, rings);
    images.push_back(std::move(image));
  }
  return images;
}

std::string png_bytes(const BakedImage& image) {
  std::string bytes;
  if (image.width <= 0 || image.height <= 0) return bytes;
  const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, image.width);
  std::vector<unsigned char> data(std::size_t(stride) * image.height);
  for (int y = 0; y < image.height; ++y)
    std::memcpy(&data[std::size_t(y) * stride], &image.argb[std::size_t(y) * image.width],
                std::size_t(image.width) * 4);
  cairo_surface_t* surface = cairo_image_surface_create_for_data(data.data(), CAIRO_FORMAT_ARGB32,
                                                                 image.width, image.height, stride);
  bytes = papercraft::png_bytes(surface);
  cairo_surface_destroy(surface);
  return bytes;
}

}  // namespace papercraft
