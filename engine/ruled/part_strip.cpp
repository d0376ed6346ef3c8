#include "engine/ruled/part_strip.h"

#include <utility>

namespace papercraft {

namespace {

// How a strip faces against its part, judged where the strip meets the part's boundary: on
// each boundary edge of the part that the strip shares, the two lie on the same side, so the
// strip's edge runs the way the part's face-side half-edge does (agrees) or against it.
// Counted apart for the edges of the strip's two boundaries (A's vertices, B's vertices);
// a ruling that happens to lie on the part's boundary counts in neither.
struct Facing {
  int a_agree = 0, a_against = 0, b_agree = 0, b_against = 0;
  int agree() const { return a_agree + b_agree; }
  int against() const { return a_against + b_against; }
};

Facing facing(const Mesh& part, const std::vector<int>& first, const std::vector<int>& second,
              const RuledStrip& strip) {
  std::vector<int> vertex_of(strip.a_count + strip.b_count, -1);
  for (int i = 0; i < strip.a_count && i < static_cast<int>(first.size()); ++i)
    vertex_of[i] = first[i];
  for (int j = 0; j < strip.b_count && j < static_cast<int>(second.size()); ++j)
    vertex_of[strip.a_count + j] = second[j];
  Facing f;
  for (const Triangle& t : strip.mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int s = t[k], e = t[(k + 1) % 3];
      if ((s < strip.a_count) != (e < strip.a_count)) continue;  // a ruling
      const int u = vertex_of[s], v = vertex_of[e];
      if (u < 0 || v < 0 || u == v) continue;
      const auto h = part.find_halfedge(part.vertex_handle(u), part.vertex_handle(v));
      if (!h.is_valid() || !part.is_boundary(part.edge_handle(h))) continue;
      const bool against = part.is_boundary(h);
      if (s < strip.a_count)
        (against ? f.a_against : f.a_agree) += 1;
      else
        (against ? f.b_against : f.b_agree) += 1;
    }
  }
  return f;
}

}  // namespace

RuledStrip part_strip(const Mesh& part, const std::vector<int>& first, const Polyline& a,
                      const std::vector<int>& second, const Polyline& b,
                      const TwistOptions& options) {
  RuledStrip strip = twist_minimizing_strip(a, b, options);
  Facing f = facing(part, first, second, strip);
  // Between two loops, the cheaper traversal of B can be the one that turns the strip inside
  // out on its way from A to B (a narrow band, where both twist little): A's side faces one
  // way, B's the other, and its piece would be glued with its back showing along B. The
  // traversal that faces one way all over is taken instead, whatever its twist.
  const bool loops = a.closed && b.closed && !a.is_point() && !b.is_point();
  const bool a_flips = f.a_against > f.a_agree, b_flips = f.b_against > f.b_agree;
  if (loops && a_flips != b_flips) {
    for (int direction : {1, -1}) {
      TwistOptions forced = options;
      forced.b_direction = direction;
      RuledStrip other = twist_minimizing_strip(a, b, forced);
      const Facing g = facing(part, first, second, other);
      if ((g.a_against > g.a_agree) == (g.b_against > g.b_agree)) {
        strip = std::move(other);
        f = g;
        break;
      }
    }
  }
  // Facing the other way all over (A taken the other way round the part): turned over, else
  // it unfolds into the mirror image of its piece, whose seams run the way their partners' do.
  if (f.against() > f.agree())
    for (Triangle& t : strip.mesh.triangles) std::swap(t[1], t[2]);
  return strip;
}

}  // namespace papercraft
