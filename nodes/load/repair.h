#pragma once
// Step 3 of loading, second part: the checks of the raw faces and of the triangle soup, and the
// safe repairs (unreferenced and duplicate vertices, non-manifold vertices, orientation).

#include <cstddef>
#include <string>
#include <vector>

#include "nodes/load/openmesh.h"
#include "nodes/load/recording_importer.h"
#include "nodes/load/soup.h"

namespace papercraft::load_internal {

/// Throws InvalidInputException for non-finite positions, faces with fewer than 3 vertices,
/// out-of-range vertex indices or a vertex repeated in a face (but for a triangle with
/// `repair`: heal_degenerate_triangles drops it).
void check_raw_faces(const RawMesh& raw, const std::string& file, bool repair = false);
/// Removes the vertices no triangle uses; returns how many.
std::size_t remove_unreferenced_vertices(Soup& soup);
/// Merges each vertex into an earlier one whose coordinates all differ from it by at most
/// `epsilon` (0: only equal positions); returns how many were merged.
std::size_t merge_duplicate_vertices(Soup& soup, double epsilon);
/// What heal_degenerate_triangles healed: `collapsed` faces had corners merged into one another
/// (dropped); `flat` faces had their corners on one line (dropped, the face across the longest
/// edge split at the middle corner).
struct DegenerateFaces {
  std::size_t collapsed = 0;
  std::size_t flat = 0;
};
/// Heals the faces check_degenerate_triangles refuses where it can without moving the surface:
/// a face with a repeated corner is dropped; a face whose corners lie on one line (twice its
/// area at most `ratio` times its longest edge squared) is dropped and the face across its
/// longest edge split at its middle corner, so that every edge keeps its faces. A flat face
/// whose longest edge has more than one other face is left as it is.
DegenerateFaces heal_degenerate_triangles(Soup& soup, double ratio);
/// Throws InvalidInputException for a triangle with a repeated vertex or with twice its area at
/// most options.degenerate_area_ratio times its longest edge squared.
void check_degenerate_triangles(const Soup& soup, const LoadOptions& options,
                                const std::string& file);
/// What remove_duplicate_triangles removed: `copies` repeat a face facing the same way;
/// `folds` are pairs facing opposite ways (both removed); `other_sides` the faces of a
/// two-sided part beside the one kept of each group.
struct DuplicateFaces {
  std::size_t copies = 0;
  std::size_t folds = 0;
  std::size_t other_sides = 0;
};
/// Removes triangles over the same three vertices as another: a copy facing the same way is
/// dropped, and a pair facing opposite ways (a flap folded flat onto itself, of no area: two
/// quads sharing three corners, each split into triangles, give one) is dropped whole. Of
/// unequal numbers facing each way, the first facing the way most do is kept. A connected part
/// whose every face is in such a pair (as many facing each way) is a two-sided surface, each
/// face written once per side as game models are: of each pair the first face is kept (the
/// orientation repair then makes them agree).
DuplicateFaces remove_duplicate_triangles(Soup& soup);
/// Throws InvalidInputException for two triangles over the same three vertices.
void check_duplicate_triangles(const Soup& soup, const std::string& file);
/// Throws InvalidInputException for non-manifold edges and non-orientable components, and without
/// `repair` for non-manifold vertices and an inconsistent orientation. With `repair`, cuts
/// non-manifold edges apart (the faces on each paired into sheets: two solids touching along an
/// edge stay two closed solids; else the flattest pairs, a face left over getting the edge as a
/// boundary; the sheets' copies of the edge's ends moved into their own sheet by at most 1e-7
/// of the bounding-box diagonal, so that no later step, which identifies seams by their 3D
/// points, takes one sheet's edge for the other's; where the sheets still meet around both
/// ends, at one end the sharpest manifold edge between each two sheets is opened too, so they
/// part; an edge where that finds none stays an error), splits non-manifold vertices, makes the
/// orientation consistent and closed components face outwards, adding one line per change to
/// `repairs`.
void check_topology_and_orient(Soup& soup, bool repair, const std::string& file,
                               std::vector<std::string>& repairs);

}  // namespace papercraft::load_internal
