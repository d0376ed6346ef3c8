#pragma once
// Step 1 of loading, the pre-scan: what a file must contain, checked before OpenMesh's reader
// sees it (see openmesh.h for why); one prescan_* per format, in prescan_<format>.cpp.

#include <cstdint>
#include <filesystem>
#include <string>

#include "nodes/load/file_scanner.h"
#include "nodes/load/openmesh.h"
#include "nodes/load/raw_mesh.h"

namespace papercraft::load_internal {

/// The formats load_mesh reads, chosen by the file's extension.
enum class Format { obj, off, ply, stl, gltf, threemf, arrays };  // arrays: load_arrays

/// What the pre-scan found: the records OpenMesh's reader must report, and what the later steps
/// need to know about the file.
struct Prescan {
  Format format = Format::obj;
  // Records OpenMesh must report (for an STL, `vertices` is 3 per triangle before welding).
  std::uint64_t vertices = 0;
  std::uint64_t faces = 0;
  std::uint64_t corners = 0;
  std::filesystem::path material_library;  // OBJ mtllib, resolved against the OBJ's folder
  std::string ply_texture;                 // PLY "comment TextureFile <name>"
  bool off_comments = false;               // an ascii OFF with '#' comments
  std::uint64_t off_face_extras = 0;       // OFF faces with values after their indices
  std::uint64_t obj_continuations = 0;     // OBJ lines ending in a backslash (go on on the next)
  /// Faces of no area that OpenMesh's reader drops, counted in `faces` and `corners` (STL
  /// triangles two of whose corners coincide, OBJ faces of fewer than 3 distinct vertices): with
  /// the repair on, their removal is logged; without it they are an error.
  std::uint64_t dropped_faces = 0;
  std::uint64_t dropped_corners = 0;
  /// The pre-scan read the records itself (a plain ascii OFF or binary PLY, given a RawMesh):
  /// OpenMesh's reader is not needed.
  bool read_natively = false;
};

/// Throws InvalidInputException when `faces` is over options.max_faces or `vertices` more than
/// OpenMesh can index.
void check_counts(const std::string& file, std::uint64_t vertices, std::uint64_t faces,
                  const LoadOptions& options);
/// Throws InvalidInputException when the records a header declares (`what`) need more bytes than
/// are `available` after it.
void check_room(const std::string& file, const std::string& what, std::uint64_t needed,
                std::uint64_t available);
/// The Prescan of a file read natively into `raw` (the scene formats): its counts, checked as
/// check_counts does.
Prescan natively_read(Format format, const RawMesh& raw, const std::string& file,
                      const LoadOptions& options);
/// Throws InvalidInputException when the file has no faces.
void check_some_faces(const std::string& file, const Prescan& scan);

// Each pre-scan reads the file once from the start and throws InvalidInputException (message
// starting with `file`) for what OpenMesh's reader would misread, drop or refuse; an IOException
// comes from the scanner.

/// OBJ: every v, vt and f line parsed; faces OpenMesh would shrink refused, and those it would
/// drop (fewer than 3 distinct vertices) counted in `dropped_faces`, an error without
/// options.repair; the first mtllib resolved against `path`'s folder. A line ending in a
/// backslash goes on on the next (counted in `obj_continuations`).
Prescan prescan_obj(FileScanner& in, const std::string& file, const std::filesystem::path& path,
                    const LoadOptions& options);
/// OFF, ascii or "OFF BINARY": the header, the counts against the file size, every record.
/// Given `raw`, a plain ascii OFF (no ST, C or N prefix) is also read into it, positions in
/// double precision, and `read_natively` is set: one pass over the file instead of two, and no
/// single-precision reader in between.
Prescan prescan_off(FileScanner& in, const std::string& file, const LoadOptions& options,
                    RawMesh* raw = nullptr);
/// PLY, ascii or binary: the header (layouts OpenMesh misreads refused), the counts against the
/// file size, the records of every element up to the faces.
/// Given `raw`, a binary PLY whose vertices have only positions (and normals) and whose faces
/// only their index lists is also read into it, positions in double precision, and
/// `read_natively` is set; so is one, ascii or binary, whose faces have a texture coordinate list
/// (`texcoord`, as MeshLab writes it), which OpenMesh's reader cannot read.
Prescan prescan_ply(FileScanner& in, const std::string& file, const LoadOptions& options,
                    RawMesh* raw = nullptr);
/// STL, binary when the size is 84 + 50 * triangles, else ascii: every triangle's corners; those
/// with two corners the same (no area) are counted in `dropped_faces`, an error without
/// options.repair.
Prescan prescan_stl(FileScanner& in, const std::string& file, const LoadOptions& options);

}  // namespace papercraft::load_internal
