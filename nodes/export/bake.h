#pragma once
// The print image of each piece, baked from the input surface: for every pixel of a piece on
// paper, the point of the 3D strip it comes from, the closest point of the input surface
// (BVH), and that face's texture at its corner UVs (bilinear) or its colours. Right across UV
// seams, between materials and on strips that cross several UV islands, and it needs no UVs on
// the strips. Tabs show the partner piece's surface across the seam. The image reaches
// `bleed_mm` beyond the cut line so a slightly wide cut shows no white.

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/appearance.h"
#include "core/bvh.h"
#include "core/mesh.h"
#include "core/pattern.h"
#include "core/strip.h"
#include "nodes/export/image.h"

namespace papercraft {

struct BakeOptions {
  double dpi = 300.0;
  double bleed_mm = 1.0;
  bool tab_texture = true;  // false: tabs are left blank
};

/// A piece's image on its page: `width` x `height` pixels of `pixel_mm`, the top-left one's
/// corner at `origin` (page mm); premultiplied ARGB32 as cairo keeps it, transparent outside
/// the piece, its tabs and their bleed.
struct BakedImage {
  Vec2 origin = Vec2::Zero();
  double pixel_mm = 0.0;
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> argb;
};

/// The colour of the input surface nearest a point.
class SurfaceSampler {
 public:
  /// `images[m]` is material m's texture, or null where it is missing (then colours, if any,
  /// else nothing). \pre appearance's arrays are empty or have one entry per face of `input`.
  SurfaceSampler(const Mesh& input, const SurfaceAppearance& appearance,
                 std::vector<std::shared_ptr<const Image>> images);

  /// Linear 0..1 RGB at the surface point nearest `p`, or false when nothing is printed there.
  /// `hint` (a triangle index, or -1) warm-starts the search and is updated.
  bool colour(const Vec3& p, int* hint, Vec3* rgb) const;

  /// A triangle that can be nearest to points near a centre, and its distance to the centre.
  struct Candidate {
    double distance;
    int triangle;
  };

  /// The triangles that can be nearest to some point within `radius` of `centre`, nearest
  /// first, when there are at most `limit` of them (else false): those within d + 2 radius of
  /// `centre`, d its distance to the surface (a point q within radius has its nearest triangle
  /// within d(q) + radius <= d + 2 radius of centre).
  bool nearest_candidates(const Vec3& centre, double radius, std::size_t limit,
                          std::vector<Candidate>& out) const;

  /// colour(p), the nearest triangle searched among `candidates` only (from
  /// nearest_candidates(centre, r) with |p - centre| <= r; ties go to the lowest index, as in
  /// colour).
  bool colour_among(const Vec3& p, const Vec3& centre, std::span<const Candidate> candidates,
                    Vec3* rgb) const;

  bool empty() const { return empty_; }

 private:
  bool shade(int triangle, const Vec3& barycentric, Vec3* rgb) const;

  TriangleBvh bvh_;
  // Per BVH triangle, in its corner order: material, uvs, colours.
  std::vector<int> material_;
  std::vector<std::array<Vec2, 3>> uv_;
  std::vector<std::array<Vec3, 3>> colour_;
  std::vector<std::shared_ptr<const Image>> images_;
  bool empty_ = true;
};

/// The images of the pieces of `page` (one per piece, in page order; pieces whose strip is
/// not in `strips` get an empty image).
std::vector<BakedImage> bake_page(const Page& page, const std::map<int, const FlatStrip*>& strips,
                                  const SurfaceSampler& sampler, const BakeOptions& options);

/// The image as a PNG file's bytes (for embedding in SVG).
std::string png_bytes(const BakedImage& image);

}  // namespace papercraft
