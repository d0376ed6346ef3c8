#pragma once
// The "load" stage: read a mesh file with OpenMesh's readers, validate it, apply the safe
// repairs and build the pipeline's `Mesh` (DESIGN.md section 2, implementation
// `load.openmesh`).
//
// OpenMesh's readers report success on broken files: a truncated ascii OFF is padded with
// repeats of its last face, a NaN in an OBJ silently drops the vertex (shifting every later
// index), a NaN in an STL is welded onto an arbitrary vertex, a header that claims 4e9 vertices
// makes the reader loop 4e9 times, a comment right before a binary PLY's end_header shifts the
// data by one byte. So a file goes through three steps:
//   1. a pre-scan (prescan.h): header counts against the file size (fails fast on absurd counts,
//      before anything is allocated), every ascii record parsed once (non-finite numbers,
//      truncation, more data than declared), binary records walked (truncation), header layouts
//      OpenMesh misreads refused;
//   2. OpenMesh's reader fills a recording importer (recording_importer.h) that keeps the raw
//      vertex positions, face index lists and texture coordinates, dropping nothing; a plain
//      ascii OFF (no ST, C or N prefix) is instead read by its pre-scan itself, in the same
//      pass and in double precision (OpenMesh's OFF reader reads single precision);
//   3. the raw data is triangulated (triangulate.h), validated and repaired (repair.h), and the
//      `Mesh` is built with add_face.
// OpenMesh's reader objects are process-wide singletons with per-file state, so step 2 is
// serialised by a mutex; steps 1 and 3 run concurrently for different files.
//
// Typical use by the load node:
//   LoadedMesh loaded = load_mesh(job.path);
//   for (const std::string& repair : loaded.repairs) spdlog::info("{}: {}", job.path, repair);

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/appearance.h"
#include "core/mesh.h"
#include "core/triangle_mesh.h"

namespace papercraft {

struct LoadOptions {
  /// Apply the safe repairs, each logged as one line of LoadedMesh::repairs: remove unreferenced
  /// vertices; merge duplicate vertices (see duplicate_vertex_epsilon); heal degenerate faces
  /// (heal_degenerate_triangles: drop one whose corners merged; drop one of zero area and split
  /// the face across its longest edge at its middle corner); remove duplicate faces
  /// (remove_duplicate_triangles: a copy facing the same way, or a pair facing opposite ways,
  /// with the vertices only that pair used; of a part made only of such pairs, a two-sided
  /// surface, one face of each pair is kept); cut non-manifold edges apart and split
  /// non-manifold vertices (check_topology_and_orient); flip faces so that
  /// neighbours agree on their orientation; flip closed components that face inwards. With
  /// `repair == false` unreferenced and duplicate vertices are kept as they are (a duplicate
  /// then opens a boundary), and degenerate and duplicate faces, non-manifold edges and
  /// vertices and an inconsistent orientation are errors.
  bool repair = true;
  /// Files declaring more faces (and meshes with more triangles after triangulation) are refused.
  std::size_t max_faces = 50'000'000;
  /// Vertices whose coordinates all differ by at most this are merged by the repair; 0 merges only
  /// exactly equal positions.
  double duplicate_vertex_epsilon = 0.0;
  /// A triangle is degenerate when twice its area is at most this times its longest edge
  /// squared; 0 refuses exactly zero areas only.
  double degenerate_area_ratio = 1e-12;
};

struct LoadedMesh {
  /// The validated mesh: triangles only, manifold (every edge has one or two faces and every
  /// vertex a single fan), consistently oriented, no degenerate or duplicate faces, no deleted
  /// elements. Vertex i carries the int property "v:input_vertex": its index in the file's
  /// vertex list (for an STL, in the list of distinct corner positions).
  Mesh mesh;
  /// All faces had texture coordinates: the vertex texcoords2D are set (the UV of one corner
  /// of the vertex). Vertices are never split at UV seams, so the surface stays closed where
  /// the file's positions are shared; where a vertex's corners disagree (uv_seam_vertices > 0)
  /// the per-corner UVs are also in halfedge texcoords2D (the halfedge of a face that points to
  /// the corner's vertex, OpenMesh's convention), which are requested only then.
  bool has_uvs = false;
  std::size_t uv_seam_vertices = 0;
  /// The OBJ's diffuse texture (map_Kd of the material used by most faces, resolved against the
  /// .mtl file's folder) or a PLY's "comment TextureFile" (against the PLY's folder); empty if
  /// none. Not checked for existence.
  std::string texture_path;
  /// Per face of `mesh`: its material (every map_Kd of an OBJ's materials, a PLY's
  /// "comment TextureFile"), corner texture coordinates and corner colours (PLY and COFF
  /// vertex colours, PLY face colours). Texture files are not checked for existence here.
  SurfaceAppearance appearance;
  /// One line per change made to the file's data, e.g. "removed 3 unreferenced vertices",
  /// "merged 12 exactly duplicate vertices", "triangulated 6 polygons into 12 triangles".
  /// An STL always gets the weld line: OpenMesh's STL reader merges equal corners itself.
  std::vector<std::string> repairs;
  /// Vertex and face records in the file (an STL has 3 vertices per triangle; a polygon counts
  /// as one face).
  std::size_t input_vertices = 0;
  std::size_t input_faces = 0;
};

/// Reads an OBJ, OFF (ascii, or plain "OFF BINARY"), PLY (ascii or binary, either endianness)
/// or STL (ascii or binary; binary whenever the size is 84 + 50 * triangles, even if the header
/// starts with "solid") file, chosen by the extension (any case). Polygons are triangulated as a
/// fan from their first corner; a polygon that is not convex (a fan triangle turns against the
/// polygon's normal) is refused. Coordinates are read as single precision by OpenMesh.
///
/// Every message starts with `path` and says what is wrong with counts and the first offender,
/// e.g. "bunny.obj: mesh has 3 non-manifold edges (shared by 3 or more faces), first at
/// vertices 12-40". Vertex and face numbers in messages are 0-based positions in the file's
/// vertex and face lists (OBJ's `f 1 2 3` is vertices 0, 1, 2); line numbers are 1-based.
/// \throws IOException the file is missing, not a regular file, unreadable, or OpenMesh's reader
///   fails on a file that passed the pre-scan.
/// \throws InvalidInputException the extension is unknown; the file is empty, truncated or
///   malformed (counts that disagree with the header, unparsable records, list or property types
///   OpenMesh's reader cannot read); it has no faces or more than options.max_faces; it has
///   non-finite (NaN, infinite, beyond single precision) coordinates, faces with fewer than 3
///   vertices or out-of-range indices, non-convex polygons, degenerate (zero-area) faces the
///   repair cannot heal,
///   non-manifold edges or vertices, or a non-orientable component; no faces left once
///   duplicate faces are removed; or (with repair off) duplicate or inconsistently oriented
///   faces.
LoadedMesh load_mesh(const std::filesystem::path& path, const LoadOptions& options = {});

/// A mesh given in memory (vertex positions, triangles), validated and repaired as load_mesh
/// does a file's; `name` starts every message as a file's path does.
/// \throws InvalidInputException as load_mesh: no faces, more than options.max_faces,
///   non-finite coordinates, out-of-range indices, what the repair cannot heal.
LoadedMesh load_arrays(const TriangleMesh& mesh, const std::string& name,
                       const LoadOptions& options = {});

}  // namespace papercraft
