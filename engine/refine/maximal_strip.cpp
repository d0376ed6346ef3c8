#include "engine/refine/maximal_strip.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>

#include "engine/ruled/part_strip.h"
#include "engine/select/geodesic.h"

namespace papercraft {

namespace {

// The boundary side of one probe: the piece on the near side of the iso-line, if it is a
// single piece whose strip (boundary -> cut loop) is within the tolerance.
struct Probe {
  bool ok = false;
  double area = 0.0;
  const Mesh* piece = nullptr;  // the strip's piece
};

int vertex_at(const Mesh& mesh, const OpenMesh::Vec3d& point) {
  for (auto v : mesh.vertices()) {
    if (mesh.point(v) == point) return v.idx();
  }
  return -1;
}

Probe probe(const Mesh& part, const std::vector<Mesh>& pieces, const std::vector<int>& side,
            bool side_closed, double tolerance, const MaximalStripOptions& options) {
  // The piece holding this side's boundary; other pieces on the same side of the iso-line
  // (if any) simply go back to the refinement loop.
  const Mesh* piece = nullptr;
  const auto anchor = part.point(part.vertex_handle(side.front()));
  for (const Mesh& p : pieces) {
    if (vertex_at(p, anchor) >= 0) {
      if (piece) return {};
      piece = &p;
    }
  }
  if (!piece) return {};
  const auto loops = boundary_loops(*piece);
  std::vector<int> cut_loop;
  std::vector<int> side_loop;
  for (const auto& loop : loops) {
    const bool is_side = std::any_of(loop.begin(), loop.end(), [&](int v) {
      return piece->point(piece->vertex_handle(v)) == anchor;
    });
    if (is_side && side_closed) {
      side_loop = loop;
    } else if (cut_loop.empty()) {
      cut_loop = loop;
    } else {
      return {};  // more loops than a strip has
    }
  }
  if (cut_loop.empty() || (side_closed && side_loop.empty())) return {};
  const Polyline cut_polyline = selection_polyline(*piece, cut_loop, true);
  if (!side_closed) side_loop = {vertex_at(*piece, anchor)};
  const Polyline side_polyline = selection_polyline(*piece, side_loop, side_closed);
  const RuledStrip strip =
      side_closed
          ? part_strip(*piece, side_loop, side_polyline, cut_loop, cut_polyline, options.twist)
          : part_strip(*piece, cut_loop, cut_polyline, side_loop, side_polyline, options.twist);
  if (strip.mesh.empty()) return {};
  const HausdorffResult result =
      decide_within(to_triangle_mesh(*piece), strip.mesh, tolerance, options.decide);
  return {result.within, surface_area(*piece), piece};
}

}  // namespace

WitnessCut cut_maximal_strip(const Mesh& part, const std::vector<int>& first, bool first_closed,
                             const std::vector<int>& second, bool second_closed, double tolerance,
                             const MaximalStripOptions& options, const OneStrip& one_strip) {
  std::vector<char> in_first(part.n_vertices(), 0);
  for (int v : first) in_first[v] = 1;
  if (std::any_of(second.begin(), second.end(), [&](int v) { return in_first[v] != 0; })) {
    return {};
  }
  const Eigen::VectorXd f = harmonic_field(part, first, second, options.cut.harmonic);
  const double margin = options.cut.margin;
  const double area = surface_area(part);
  // The two sides are independent searches: run them side by side.
  MaximalStripOptions probe_options = options;
  probe_options.decide.bounded.locate_maximum = false;  // a probe needs the decision only
  struct Side {
    WitnessCut cut;
    double area = 0.0;
  };
  auto search = [&](bool low_side) {
    const std::vector<int>& side = low_side ? first : second;
    const bool closed = low_side ? first_closed : second_closed;
    // Bisection on the distance d from this side's boundary: d = value (low) or 1 - value.
    double good = 0.0, bad = 1.0;
    const double least = std::max(options.cut.min_piece_fraction, options.min_strip_fraction);
    Side found;
    for (int step = 0; step < options.steps; ++step) {
      const double d = std::clamp(0.5 * (good + bad), margin, 1.0 - margin);
      const double value = low_side ? d : 1.0 - d;
      std::vector<Mesh> pieces = cut_along_isoline(part, f, value, options.cut.cut);
      const Probe result =
          pieces.size() < 2 ? Probe{} : probe(part, pieces, side, closed, tolerance, probe_options);
      bool big_enough = result.ok && result.area >= least * area &&
                        area - result.area >= options.cut.min_piece_fraction * area;
      // Limits: a strip too narrow or small is no answer, but a larger one may be; a rest too
      // narrow or small asks for a smaller strip.
      bool record = big_enough;
      if (big_enough && options.cut.limits.active()) {
        for (const Mesh& piece : pieces) {
          if (piece_shortfall_ahead(piece, options.cut.limits, one_strip) == 0.0) continue;
          record = false;
          if (&piece != result.piece) big_enough = false;
        }
      }
      if (big_enough) {
        good = d;
        if (record) found = {{std::move(pieces), value, false}, result.area};
      } else {
        bad = d;
      }
    }
    return found;
  };
  Side low, high;
  tbb::parallel_invoke([&] { low = search(true); }, [&] { high = search(false); });
  if (low.cut.pieces.empty() && high.cut.pieces.empty()) return {};
  return std::move(high.area > low.area ? high.cut : low.cut);
}

}  // namespace papercraft
