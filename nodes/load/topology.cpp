// check_topology_and_orient: faces joined across their edges (non-manifold edges cut apart
// into sheets with `repair`), non-manifold vertices split per fan, the orientation made
// consistent and closed components turned to face outwards.
#include <algorithm>
#include <climits>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/union_find.h"
#include "nodes/load/messages.h"
#include "nodes/load/non_manifold_edges.h"
#include "nodes/load/repair.h"

namespace papercraft::load_internal {
namespace {

// Every edge use, sorted by (key, slot): bucketed by the lower vertex in slot order (a counting
// sort), then each bucket, a vertex's few edges, stably sorted by the higher vertex.
void sort_edge_uses(const Soup& soup, std::vector<EdgeUse>& uses) {
  std::vector<std::uint32_t> start(soup.positions.size() + 1, 0);
  auto lower = [&](std::size_t slot) {
    const int a = soup.triangles[slot / 3][slot % 3];
    const int b = soup.triangles[slot / 3][(slot % 3 + 1) % 3];
    return static_cast<std::uint32_t>(std::min(a, b));
  };
  for (std::size_t slot = 0; slot < uses.size(); ++slot) ++start[lower(slot) + 1];
  for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t slot = 0; slot < uses.size(); ++slot) {
    const auto a = static_cast<std::uint32_t>(soup.triangles[slot / 3][slot % 3]);
    const auto b = static_cast<std::uint32_t>(soup.triangles[slot / 3][(slot % 3 + 1) % 3]);
    uses[fill[std::min(a, b)]++] = {(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b),
                                    static_cast<std::uint32_t>(slot)};
  }
  for (std::size_t v = 0; v + 1 < start.size(); ++v)
    std::stable_sort(uses.begin() + start[v], uses.begin() + start[v + 1],
                     [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });
}

// The faces joined across their edges: neighbours, the fans of every vertex, and what was found
// on the way.
struct FaceJoins {
  std::vector<int> neighbor;  // neighbor[3 t + k]: the triangle across edge k of t, or -1
  UnionFind fans{0};          // corner slots in one fan of their vertex
  std::uint64_t non_manifold = 0, inconsistent = 0, cut_apart = 0;
  std::size_t first_non_manifold = 0, first_inconsistent = 0;  // positions in `uses`
  std::vector<char> on_cut_edge;       // vertices at the ends of edges cut apart
  std::vector<std::size_t> cut_edges;  // where each edge cut apart starts in `uses`
  std::vector<std::uint64_t> parting;  // manifold edges left unjoined so sheets part
};

// Joins the faces across every edge of two faces and, with `repair`, across the sheets of every
// non-manifold edge; where those sheets still meet around both ends, once more with the
// manifold edges parting_edges opens left unjoined.
FaceJoins join_faces(const Soup& soup, const std::vector<EdgeUse>& uses, bool repair) {
  const std::size_t triangles = soup.triangles.size();
  FaceJoins joins;
  // The two faces of edge uses s1 and s2 (at uses[i]) as neighbours across it.
  const auto join = [&](std::uint32_t s1, std::uint32_t s2, std::size_t i) {
    const std::uint32_t t1 = s1 / 3, t2 = s2 / 3;
    joins.neighbor[s1] = static_cast<int>(t2);
    joins.neighbor[s2] = static_cast<int>(t1);
    const Triangle3& a = soup.triangles[t1];
    const Triangle3& b = soup.triangles[t2];
    const int from = a[s1 % 3];
    const int to = a[(s1 % 3 + 1) % 3];
    if (b[s2 % 3] == from && joins.inconsistent++ == 0) joins.first_inconsistent = i;
    // The two faces are neighbours in the fans of both edge ends.
    joins.fans.unite(s1 - s1 % 3 + corner_of(a, from), s2 - s2 % 3 + corner_of(b, from));
    joins.fans.unite(s1 - s1 % 3 + corner_of(a, to), s2 - s2 % 3 + corner_of(b, to));
  };
  std::vector<std::uint64_t>& parting = joins.parting;
  for (int pass = 0; pass < 2; ++pass) {
    joins.neighbor.assign(3 * triangles, -1);
    joins.fans = UnionFind(3 * triangles);
    joins.non_manifold = joins.inconsistent = joins.cut_apart = 0;
    joins.on_cut_edge.assign(repair ? soup.positions.size() : 0, 0);
    joins.cut_edges.clear();
    for (std::uint64_t key : parting)
      joins.on_cut_edge[key >> 32] = joins.on_cut_edge[key & 0xffffffffu] = 1;
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i + 1;
      while (j < uses.size() && uses[j].key == uses[i].key) ++j;
      if (j - i >= 3) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> sheets;
        if (repair) sheets = sheets_around_edge(soup, uses[i].key, slots_of(uses, i, j));
        if (sheets.empty()) {
          if (joins.non_manifold++ == 0) joins.first_non_manifold = i;
        } else {
          for (const auto& [s1, s2] : sheets) join(s1, s2, i);
          joins.on_cut_edge[uses[i].key >> 32] = joins.on_cut_edge[uses[i].key & 0xffffffffu] = 1;
          joins.cut_edges.push_back(i);
          ++joins.cut_apart;
        }
      } else if (j - i == 2 && !std::binary_search(parting.begin(), parting.end(), uses[i].key)) {
        join(uses[i].slot, uses[i + 1].slot, i);
      }
      i = j;
    }
    if (pass == 1 || joins.non_manifold > 0 || joins.cut_edges.empty()) break;
    std::unordered_set<std::uint64_t> cut_keys;
    for (std::size_t i : joins.cut_edges) cut_keys.insert(uses[i].key);
    for (std::size_t i : joins.cut_edges) {
      std::size_t j = i + 1;
      while (j < uses.size() && uses[j].key == uses[i].key) ++j;
      parting_edges(soup, joins.neighbor, joins.fans, uses[i].key, slots_of(uses, i, j), cut_keys,
                    parting);
    }
    std::sort(parting.begin(), parting.end());
    parting.erase(std::unique(parting.begin(), parting.end()), parting.end());
    if (parting.empty()) break;
  }
  return joins;
}

// Names an edge and the faces on it in messages.
struct EdgeNames {
  const Soup& soup;
  const std::vector<EdgeUse>& uses;
  std::string vertices(std::uint64_t key) const {
    return std::to_string(soup.source_vertex[key >> 32]) + "-" +
           std::to_string(soup.source_vertex[key & 0xffffffffu]);
  }
  std::string face(std::uint32_t slot) const { return std::to_string(soup.source_face[slot / 3]); }
  // The faces on the edge that starts at uses[first].
  std::string faces(std::size_t first) const {
    std::string list;
    for (std::size_t k = first; k < uses.size() && uses[k].key == uses[first].key; ++k)
      list += (list.empty() ? "" : ", ") + face(uses[k].slot);
    return list;
  }
};

// The vertices whose corners lie in more than one fan, and the first fan of each vertex.
struct VertexFans {
  std::vector<std::int64_t> fan_of_vertex;
  std::vector<char> bad_vertex;
  std::uint64_t non_manifold = 0;
};

VertexFans vertex_fans(const Soup& soup, FaceJoins& joins) {
  const std::size_t vertices = soup.positions.size();
  VertexFans v;
  v.fan_of_vertex.assign(vertices, -1);
  v.bad_vertex.assign(vertices, 0);
  for (std::size_t slot = 0; slot < 3 * soup.triangles.size(); ++slot) {
    const int vertex = soup.triangles[slot / 3][slot % 3];
    const auto root = static_cast<std::uint32_t>(joins.fans.find(slot));
    if (v.fan_of_vertex[vertex] < 0) {
      v.fan_of_vertex[vertex] = root;
    } else if (v.fan_of_vertex[vertex] != root) {
      v.bad_vertex[vertex] = 1;
    }
  }
  v.non_manifold =
      static_cast<std::uint64_t>(std::count(v.bad_vertex.begin(), v.bad_vertex.end(), 1));
  return v;
}

// Every fan of a vertex after its first gets a copy of the vertex (same position, same input
// vertex): the surface is unchanged and becomes manifold, pieces merely touch there. A fan root
// is a slot, so it names one fan of one vertex. The copies at the ends of edges cut apart are
// moved into their own sheet.
void split_non_manifold_vertices(Soup& soup, FaceJoins& joins, const VertexFans& fans,
                                 std::vector<std::string>& repairs) {
  const std::size_t vertices = soup.positions.size();
  std::unordered_map<std::uint32_t, int> copy_of_fan;
  std::vector<int> copied_from;
  for (std::size_t slot = 0; slot < 3 * soup.triangles.size(); ++slot) {
    int& corner = soup.triangles[slot / 3][slot % 3];
    const int v = corner;
    if (!fans.bad_vertex[v]) continue;
    const auto root = static_cast<std::uint32_t>(joins.fans.find(slot));
    if (fans.fan_of_vertex[v] == root) continue;
    const auto [it, added] = copy_of_fan.try_emplace(root, static_cast<int>(soup.positions.size()));
    if (added) {
      soup.positions.push_back(soup.positions[v]);
      soup.source_vertex.push_back(soup.source_vertex[v]);
      copied_from.push_back(v);
    }
    corner = it->second;
  }
  if (joins.cut_apart > 0) {
    const double moved = move_copies_apart(soup, joins.on_cut_edge, vertices, copied_from);
    std::ostringstream what;
    what << "cut " << counted(joins.cut_apart, "non-manifold edge", "non-manifold edges")
         << " apart (the faces on each paired into sheets that each pass it as a surface does; "
            "the copies of its ends moved into their own sheet by at most "
         << moved << ", so the sheets do not share a point)";
    repairs.push_back(what.str());
  }
  if (!joins.parting.empty()) {
    repairs.push_back(
        "opened " + counted(joins.parting.size(), "edge", "edges") +
        " next to non-manifold edges whose sheets met again around both ends (at one end, "
        "between each two sheets, the edge of the sharpest crease), so those sheets part there");
  }
  repairs.push_back(
      "split " + counted(fans.non_manifold, "non-manifold vertex", "non-manifold vertices") +
      " into one vertex per fan (" + counted(copy_of_fan.size(), "copy", "copies") + " added)");
}

// A cut edge whose sheets still meet at both of its ends (their fans there joined by other
// faces) is still one edge of three or more faces: an error, as without the cut.
void check_cut_edges_parted(const Soup& soup, const std::vector<EdgeUse>& uses,
                            const FaceJoins& joins, const EdgeNames& names,
                            const std::string& file) {
  std::uint64_t still_joined = 0;
  std::size_t first_joined = 0;
  for (std::size_t i : joins.cut_edges) {
    std::map<std::pair<int, int>, int> faces_on;
    bool joined = false;
    for (std::size_t k = i; k < uses.size() && uses[k].key == uses[i].key; ++k) {
      const Triangle3& t = soup.triangles[uses[k].slot / 3];
      const int from = t[uses[k].slot % 3], to = t[(uses[k].slot % 3 + 1) % 3];
      joined = joined || ++faces_on[{std::min(from, to), std::max(from, to)}] > 2;
    }
    if (joined && still_joined++ == 0) first_joined = i;
  }
  if (still_joined > 0)
    throw_invalid(file, "mesh has " +
                            counted(still_joined, "non-manifold edge", "non-manifold edges") +
                            " (shared by 3 or more faces) whose sheets meet again at both ends, "
                            "so they cannot be cut apart there, first at vertices " +
                            names.vertices(uses[first_joined].key) + " (faces " +
                            names.faces(first_joined) + ")");
}

// Components through manifold edges; flip[t] makes every neighbour pair agree (paper-free
// standard breadth-first propagation), keeping each component's majority orientation; closed
// components then face outwards (their signed volume positive). `pre_oriented`: faces
// orient_across_manifold_edges flipped already.
void orient_components(Soup& soup, const std::vector<int>& neighbor, std::uint64_t pre_oriented,
                       const std::string& file, std::vector<std::string>& repairs) {
  const std::size_t triangles = soup.triangles.size();
  std::vector<int> component(triangles, -1);
  std::vector<char> flip(triangles, 0);
  std::vector<std::uint32_t> members;
  std::vector<std::uint32_t> stack;
  std::uint64_t reoriented = 0, flipped_components = 0, flipped_faces = 0;
  int components = 0;
  for (std::size_t seed = 0; seed < triangles; ++seed) {
    if (component[seed] >= 0) continue;
    members.clear();
    component[seed] = components;
    stack.push_back(static_cast<std::uint32_t>(seed));
    bool closed = true;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      members.push_back(t);
      const Triangle3& tri = soup.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const int u = neighbor[3 * t + k];
        if (u < 0) {
          closed = false;
          continue;
        }
        const Triangle3& other = soup.triangles[u];
        const int from = tri[k];
        const int ku = corner_of(other, from);
        const bool same_direction = other[(ku + 1) % 3] == tri[(k + 1) % 3];
        const char wanted = static_cast<char>(flip[t] ^ (same_direction ? 1 : 0));
        if (component[u] < 0) {
          component[u] = components;
          flip[u] = wanted;
          stack.push_back(static_cast<std::uint32_t>(u));
        } else if (flip[u] != wanted) {
          throw_invalid(file,
                        "mesh has a non-orientable component (like a Moebius strip), "
                        "containing face " +
                            std::to_string(soup.source_face[t]));
        }
      }
    }
    std::size_t flips = 0;
    for (std::uint32_t t : members) flips += flip[t];
    if (2 * flips > members.size()) {
      for (std::uint32_t t : members) flip[t] ^= 1;
      flips = members.size() - flips;
    }
    reoriented += flips;
    if (closed) {
      // Signed volume (divergence theorem), relative to a point of the component for precision.
      const Vec3d origin = soup.positions[soup.triangles[members.front()][0]];
      double volume = 0.0;
      for (std::uint32_t t : members) {
        const Triangle3& tri = soup.triangles[t];
        const Vec3d a = soup.positions[tri[0]] - origin;
        Vec3d b = soup.positions[tri[1]] - origin;
        Vec3d c = soup.positions[tri[2]] - origin;
        if (flip[t]) std::swap(b, c);
        volume += OpenMesh::dot(a, cross(b, c));
      }
      if (volume < 0.0) {
        for (std::uint32_t t : members) flip[t] ^= 1;
        ++flipped_components;
        flipped_faces += members.size();
        reoriented -= flips;
      }
    }
    ++components;
  }
  for (std::size_t t = 0; t < triangles; ++t) {
    if (!flip[t]) continue;
    std::swap(soup.triangles[t][1], soup.triangles[t][2]);
    if (!soup.corner_uv.empty()) std::swap(soup.corner_uv[t][1], soup.corner_uv[t][2]);
  }
  reoriented += pre_oriented;
  if (reoriented > 0) {
    repairs.push_back("reoriented " + counted(reoriented, "face", "faces") +
                      " to agree with their neighbours");
  }
  if (flipped_components > 0) {
    repairs.push_back(
        "flipped " +
        counted(flipped_components, "closed component that faced", "closed components that faced") +
        " inwards (" + counted(flipped_faces, "face", "faces") + ")");
  }
}

}  // namespace

void check_topology_and_orient(Soup& soup, bool repair, const std::string& file,
                               std::vector<std::string>& repairs) {
  std::vector<EdgeUse> uses(3 * soup.triangles.size());
  sort_edge_uses(soup, uses);
  if (repair) check_not_a_volume_mesh(uses, file);
  // The faces around a non-manifold edge are paired into sheets by the way they run, which means
  // something only where they agree with their neighbours: a two-sided surface keeps one face of
  // each pair whichever way it faces, and paired as they lay its sheets made a Moebius strip
  // (trimesh's chair_model). So first the faces are made to agree across the edges of two faces.
  std::uint64_t pre_oriented = 0;
  if (repair) {
    pre_oriented = orient_across_manifold_edges(soup, uses);
    if (pre_oriented > 0) sort_edge_uses(soup, uses);
  }
  const EdgeNames names{soup, uses};
  FaceJoins joins = join_faces(soup, uses, repair);
  if (joins.non_manifold > 0)
    throw_invalid(file, "mesh has " +
                            counted(joins.non_manifold, "non-manifold edge", "non-manifold edges") +
                            " (shared by 3 or more faces), first at vertices " +
                            names.vertices(uses[joins.first_non_manifold].key) + " (faces " +
                            names.faces(joins.first_non_manifold) + ")");
  const std::size_t vertices = soup.positions.size();
  const VertexFans fans = vertex_fans(soup, joins);
  if (fans.non_manifold > 0 && repair) split_non_manifold_vertices(soup, joins, fans, repairs);
  check_cut_edges_parted(soup, uses, joins, names, file);
  if (fans.non_manifold > 0 && !repair) {
    int first = INT_MAX;
    for (std::size_t v = 0; v < vertices; ++v) {
      if (fans.bad_vertex[v]) first = std::min(first, soup.source_vertex[v]);
    }
    throw_invalid(
        file, "mesh has " +
                  counted(fans.non_manifold, "non-manifold vertex", "non-manifold vertices") +
                  " (their faces form more than one fan), first vertex " + std::to_string(first));
  }
  if (joins.inconsistent > 0 && !repair) {
    throw_invalid(file, "mesh is not consistently oriented: " +
                            counted(joins.inconsistent, "edge is", "edges are") +
                            " traversed in the same direction by both of its faces, first at "
                            "vertices " +
                            names.vertices(uses[joins.first_inconsistent].key) + " (faces " +
                            names.face(uses[joins.first_inconsistent].slot) + ", " +
                            names.face(uses[joins.first_inconsistent + 1].slot) + ")");
  }
  if (!repair) return;
  orient_components(soup, joins.neighbor, pre_oriented, file, repairs);
}

}  // namespace papercraft::load_internal
