#pragma once
// The repair of non-manifold edges behind check_topology_and_orient (repair.h): the faces on
// such an edge paired into sheets, the manifold edges to open so the sheets part at one end,
// the copies of the edge's ends moved apart, volume meshes refused, and the faces made to
// agree across manifold edges before the pairing.

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/union_find.h"
#include "nodes/load/soup.h"

namespace papercraft::load_internal {

/// One face's use of an edge.
struct EdgeUse {
  std::uint64_t key;   // (lower vertex << 32) | higher vertex
  std::uint32_t slot;  // 3 * triangle + k: the edge from corner k to corner k + 1
};

/// The slots of uses[begin, end).
inline std::vector<std::uint32_t> slots_of(const std::vector<EdgeUse>& uses, std::size_t begin,
                                           std::size_t end) {
  std::vector<std::uint32_t> slots;
  for (std::size_t i = begin; i < end; ++i) slots.push_back(uses[i].slot);
  return slots;
}

/// The faces on a non-manifold edge (its uses `slots`, edge `key` a < b) paired into sheets that
/// each pass the edge as a manifold surface would, each pair two faces next to each other in the
/// order of their third corner's angle about the edge, running opposite ways. Where the faces
/// alternate in direction around the edge, a face running b -> a (its back, the inside of a
/// consistently oriented surface, toward increasing angle) goes with the next: two solids
/// touching along an edge stay two solids, each closed. Otherwise (an odd number: a fin on a
/// surface, or directions that do not alternate) as many pairs as can be made, of those the
/// flattest (the angle between the two faces of a pair nearest a half turn), of faces running
/// opposite ways where there are such (else of any: the orientation is repaired later); a face
/// left over gets the edge as a boundary. Empty when a face has no extent away from the edge or
/// there are more than kMostFaces.
std::vector<std::pair<std::uint32_t, std::uint32_t>> sheets_around_edge(
    const Soup& soup, std::uint64_t key, const std::vector<std::uint32_t>& slots);

/// Where the sheets of a non-manifold edge (key a < b, its uses `slots`, each pair of a sheet
/// joined in `neighbor`, a face left over not) still meet around one of its ends, the manifold
/// edges at that end to leave unjoined so that every sheet there lies in a fan of its own. The
/// faces around a vertex, joined across its edges, form paths and cycles (each face has two
/// edges at the vertex, each edge joins two faces); the sheets are places on them, a joined pair
/// across a-b or a face left over (the end of a path). Between each two places next to each
/// other on one path or cycle the edge whose faces meet at the sharpest angle is left unjoined:
/// the surface gets a slit there, along a crease where one shows least. Of the two ends, the one
/// that needs fewer such edges; none when the sheets already part at one end. False when between
/// two places at both ends there is no manifold edge (`non_manifold` lists the other
/// non-manifold edges).
bool parting_edges(const Soup& soup, const std::vector<int>& neighbor, UnionFind& fans,
                   std::uint64_t key, const std::vector<std::uint32_t>& slots,
                   const std::unordered_set<std::uint64_t>& non_manifold,
                   std::vector<std::uint64_t>& parting);

/// Moves each copy of a vertex (at `first_copy` and after, copy c made from vertex copied_from[c])
/// whose original `on_cut_edge` marks into
/// its own fan, toward the mean of its faces' centroids, by 1e-7 of the mesh's bounding-box
/// diagonal or a thousandth of its shortest edge, whichever is less: sheets cut apart at a
/// non-manifold edge then share no point, so no later step can take one sheet's edge for the
/// other's. Returns the largest move.
double move_copies_apart(Soup& soup, const std::vector<char>& on_cut_edge, std::size_t first_copy,
                         const std::vector<int>& copied_from);

/// A volume mesh (the cells of a grid or a tetrahedralisation, each inner face written once) is
/// no surface to print: nearly every edge inside it is shared by three or more faces, where a
/// surface has them only where sheets touch by accident. Cut apart, its cells would print as
/// thousands of closed boxes, after a refinement of many minutes (libigl's cube_40k: 8,000
/// cubes, over 400 s). Refused when more than kVolumeShare of its edges (and at least
/// kVolumeEdges) are shared by three or more faces. `uses` sorted by key.
void check_not_a_volume_mesh(const std::vector<EdgeUse>& uses, const std::string& file);

/// Where the mesh has a non-manifold edge: the faces of each part joined across edges of exactly
/// two faces flipped to agree with their neighbours (the part's majority way kept), before its
/// non-manifold edges are paired into sheets. A part that cannot agree (a Moebius strip) is left
/// as it is, for the check after the pairing to name. `uses` sorted by key, as
/// check_topology_and_orient sorts them. Returns the number of faces flipped.
std::uint64_t orient_across_manifold_edges(Soup& soup, const std::vector<EdgeUse>& uses);

}  // namespace papercraft::load_internal
