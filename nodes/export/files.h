#pragma once
// The per-model output files of DESIGN.md section 4 (besides the pattern SVG/PDF, see
// svg.h and pdf.h). Each function returns the file's text; the caller writes it atomically.

#include <string>
#include <vector>

#include "core/build_order.h"
#include "core/mesh.h"
#include "core/pattern.h"
#include "core/strip.h"

namespace papercraft {

/// approximation.obj: the 3D strips, one `g strip_<id>` group per strip (id = index).
/// Vertices are shared within a strip, not between strips (strips meet edge to edge).
std::string approximation_obj(const std::vector<const RuledStrip*>& strips);

/// strips.json: every flat strip with id, source_strip, vertices3d, vertices2d, triangles,
/// uv (when present) and boundary edges with kind cut | seam | open, neighbour and label.
std::string strips_json(const std::vector<FlatStrip>& strips);

/// pieces.json: every printed piece, in number order: its name, strip id, piece index and
/// count (a strip split for the page), page (1-based), page transform (strip vertices2d in
/// model units -> page mm: `linear` row-major 2x2, `translation`, `rotation_degrees`), and
/// its seams (printed label, the piece across, whether this side carries the tab), and its
/// place in `order`: `step`, `part`, `glue_to` (the built piece it is glued to first) and
/// `glue` (the seams glued at its step: label, partner, length_mm, closes_loop).
std::string pieces_json(const PatternLayout& layout, const BuildOrder& order);

/// Unsigned distance of every vertex of `mesh` to the surface `to` (BVH, exact).
std::vector<double> vertex_distances(const Mesh& mesh, const TriangleMesh& to);

/// error.ply (ascii): the mesh with per-vertex colour from green (0) through blue to red
/// (>= `red_at`) and a `quality` property holding the distance itself.
std::string error_ply(const Mesh& mesh, const std::vector<double>& distances, double red_at);

}  // namespace papercraft
