// The plain ascii OFF and binary PLY read by the pre-scan itself (prescan_off and prescan_ply
// with a RawMesh) against OpenMesh's reader on the same files: the same faces and corners, and
// positions that round to OpenMesh's single-precision values; the native read keeps double
// precision.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/errors.h"
#include "core/generate.h"
#include "nodes/load/openmesh.h"
#include "nodes/load/prescan.h"
#include "nodes/load/recording_importer.h"

namespace papercraft::load_internal {
namespace {

namespace fs = std::filesystem;

struct TempFile {
  fs::path path;
  explicit TempFile(const std::string& text, const std::string& extension = ".off") {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("papercraft-native-off-" + std::to_string(::getpid()) + "-" +
            std::to_string(counter++) + extension);
    std::ofstream(path, std::ios::binary) << text;
  }
  ~TempFile() {
    std::error_code ignored;
    fs::remove(path, ignored);
  }
};

struct Reads {
  bool native = false;  // the pre-scan read it (a plain OFF)
  RawMesh raw;          // native read
  RawMesh openmesh;     // OpenMesh's read of the same file
};

// Both reads, or nothing when the pre-scan refuses the file (then neither reader is used).
std::optional<Reads> both_reads(const fs::path& path) {
  Reads reads;
  Prescan scan;
  try {
    FileScanner in(path, path.string(), fs::file_size(path));
    scan = path.extension() == ".ply" ? prescan_ply(in, path.string(), {}, &reads.raw)
                                      : prescan_off(in, path.string(), {}, &reads.raw);
  } catch (const InvalidInputException&) {
    return std::nullopt;
  } catch (const IOException&) {
    return std::nullopt;
  }
  reads.native = scan.read_natively;
  try {
    reads.openmesh = read_with_openmesh(path, path.string(), scan);
  } catch (const IOException&) {
    return std::nullopt;  // OpenMesh's reader failed
  }
  return reads;
}

void expect_same_records(const Reads& reads, const std::string& what) {
  ASSERT_EQ(reads.raw.positions.size(), reads.openmesh.positions.size()) << what;
  for (std::size_t v = 0; v < reads.raw.positions.size(); ++v)
    for (int k = 0; k < 3; ++k) {
      const float native = static_cast<float>(reads.raw.positions[v][k]);
      const double openmesh = reads.openmesh.positions[v][k];
      if (std::isnan(native) && std::isnan(openmesh)) continue;  // validation refuses both
      ASSERT_EQ(native, openmesh) << what << ": vertex " << v;
    }
  EXPECT_EQ(reads.raw.face_start, reads.openmesh.face_start) << what;
  EXPECT_EQ(reads.raw.corners, reads.openmesh.corners) << what;
}

std::string off_text(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  for (const Vec3& p : mesh.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return out.str();
}

// Whether every corner names a vertex (otherwise validation refuses the file whichever reader
// read it; OpenMesh's wraps indices beyond 32 bits).
bool indices_in_range(const RawMesh& raw) {
  for (int c : raw.corners)
    if (c < 0 || static_cast<std::size_t>(c) >= raw.positions.size()) return false;
  return true;
}

// A binary PLY of `mesh`: positions as float or double (and normals when asked), in either byte
// order, with int indices.
std::string ply_bytes(const TriangleMesh& mesh, bool big_endian, bool doubles, bool normals) {
  std::ostringstream out;
  const char* real = doubles ? "double" : "float";
  out << "ply\nformat " << (big_endian ? "binary_big_endian" : "binary_little_endian")
      << " 1.0\nelement vertex " << mesh.vertices.size() << "\nproperty " << real
      << " x\nproperty " << real << " y\nproperty " << real << " z\n";
  if (normals) out << "property float nx\nproperty float ny\nproperty float nz\n";
  out << "element face " << mesh.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  auto put = [&](const void* value, int size) {
    char bytes[8];
    std::memcpy(bytes, value, size);
    if (big_endian) std::reverse(bytes, bytes + size);
    out.write(bytes, size);
  };
  for (const Vec3& p : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      if (doubles) {
        put(&p[k], 8);
      } else {
        const float f = static_cast<float>(p[k]);
        put(&f, 4);
      }
    }
    if (normals) {
      const float n[3] = {0.0f, 0.0f, 1.0f};
      for (float f : n) put(&f, 4);
    }
  }
  for (const Triangle& t : mesh.triangles) {
    out.put(3);
    for (int v : t) put(&v, 4);
  }
  return out.str();
}

TEST(NativePly, BinaryShapesMatchOpenMeshAndKeepDoublePrecision) {
  const TriangleMesh mesh = generate_shape("pawn", {});
  for (bool big_endian : {false, true}) {
    for (bool doubles : {false, true}) {
      for (bool normals : {false, true}) {
        const std::string what = std::string(big_endian ? "big" : "little") + " endian, " +
                                 (doubles ? "double" : "float") + (normals ? ", normals" : "");
        const TempFile file(ply_bytes(mesh, big_endian, doubles, normals), ".ply");
        const auto reads = both_reads(file.path);
        ASSERT_TRUE(reads) << what;
        EXPECT_TRUE(reads->native) << what;
        expect_same_records(*reads, what);
        if (!doubles) continue;
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
          ASSERT_EQ(Vec3(reads->raw.positions[v][0], reads->raw.positions[v][1],
                         reads->raw.positions[v][2]),
                    mesh.vertices[v])
              << what << ": vertex " << v << " lost precision";
      }
    }
  }
}

TEST(NativePly, ColouredOrAsciiPlyGoesToOpenMesh) {
  const TempFile coloured(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
      ".ply");
  const auto reads = both_reads(coloured.path);
  ASSERT_TRUE(reads);
  EXPECT_FALSE(reads->native);
}

// Found by fuzz_load_ply (UBSan: a null pointer given to memcpy): a face listing no corners is
// read as an empty face, and load_mesh refuses the file with a message.
TEST(NativePly, FaceWithoutCornersIsAnEmptyRecordAndRefused) {
  const fs::path file = fs::path(PAPERCRAFT_SOURCE_DIR) /
                        "fuzz/regressions/load_ply/native-binary-face-without-corners.ply";
  RawMesh raw;
  FileScanner in(file, file.string(), fs::file_size(file));
  const Prescan scan = prescan_ply(in, file.string(), {}, &raw);
  ASSERT_TRUE(scan.read_natively);
  ASSERT_EQ(raw.n_faces(), 2u);
  EXPECT_EQ(raw.face_start[1] - raw.face_start[0], 0u);
  try {
    load_mesh(file);
    FAIL() << "a face without corners was accepted";
  } catch (const InvalidInputException& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

// Compares both reads of every file of fuzz/corpus/load_<format> and its regressions that the
// pre-scan reads natively with indices in range; returns how many it compared.
int compare_fuzz_corpus(const std::string& format) {
  int compared = 0;
  for (const std::string folder : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(PAPERCRAFT_SOURCE_DIR) / "fuzz" / folder / ("load_" + format);
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)), {});
      const TempFile file(text, "." + format);
      const auto reads = both_reads(file.path);
      if (!reads || !reads->native || !indices_in_range(reads->raw)) continue;
      expect_same_records(*reads, entry.path().filename().string());
      ++compared;
    }
  }
  return compared;
}

// Every binary PLY of the fuzzing corpus that the pre-scan accepts and whose indices are in
// range reads the same both ways.
TEST(NativePly, FuzzCorpusMatchesOpenMesh) { EXPECT_GT(compare_fuzz_corpus("ply"), 3); }

TEST(NativeOff, GeneratedShapesMatchOpenMeshAndKeepDoublePrecision) {
  for (const std::string& name : shape_names()) {
    const TriangleMesh mesh = generate_shape(name, {});
    const TempFile file(off_text(mesh));
    const auto reads = both_reads(file.path);
    ASSERT_TRUE(reads) << name;
    EXPECT_TRUE(reads->native) << name;
    expect_same_records(*reads, name);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      ASSERT_EQ(Vec3(reads->raw.positions[v][0], reads->raw.positions[v][1],
                     reads->raw.positions[v][2]),
                mesh.vertices[v])
          << name << ": vertex " << v << " lost precision";
  }
}

TEST(NativeOff, CommentsFaceExtrasAndPolygonsMatchOpenMesh) {
  const TempFile file(
      "# a comment before the keyword\n\nOFF\n# counts follow\n5 3 0\n0 0 0\n1 0 0 # end\n"
      "1 1 0\n0 1 0\n0.5 0.5 1e-3\n4 0 1 2 3 0.1 0.2 0.3\n3 0 1 4\n3 1 2 4 255 0 0\n");
  const auto reads = both_reads(file.path);
  ASSERT_TRUE(reads);
  EXPECT_TRUE(reads->native);
  expect_same_records(*reads, "hand-written");
  EXPECT_EQ(reads->raw.face_start, (std::vector<std::size_t>{0, 4, 7, 10}));
}

TEST(NativeOff, PrefixedOffGoesToOpenMesh) {
  const TempFile file("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n");
  const auto reads = both_reads(file.path);
  ASSERT_TRUE(reads);
  EXPECT_FALSE(reads->native);
}

// Every OFF of the fuzzing corpus that the pre-scan accepts and whose indices are in range
// reads the same both ways.
TEST(NativeOff, FuzzCorpusMatchesOpenMesh) { EXPECT_GT(compare_fuzz_corpus("off"), 20); }

// With PAPERCRAFT_MESHES set (bench/cgal_meshes.sh prints such a folder), every *.off in it.
TEST(NativeOff, MeshFolderMatchesOpenMesh) {
  const char* folder = std::getenv("PAPERCRAFT_MESHES");
  if (folder == nullptr) GTEST_SKIP() << "PAPERCRAFT_MESHES is not set";
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".off") continue;
    const auto reads = both_reads(entry.path());
    if (!reads || !reads->native) continue;
    expect_same_records(*reads, entry.path().filename().string());
    ++compared;
  }
  EXPECT_GT(compared, 0);
  std::printf("compared %d files\n", compared);
}

}  // namespace
}  // namespace papercraft::load_internal
