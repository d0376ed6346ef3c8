// Load throughput of the "load" stage: load_mesh (pre-scan, OpenMesh reader into a recording
// importer, validation, repairs, Mesh construction; nodes/load/openmesh.h) against a plain
// OpenMesh::IO::read_mesh of the same file into the same Mesh type, so the cost of validation
// is the ratio of the two in the same run. Counter "faces/s" is triangles of the loaded mesh
// per second of wall time (a polygon counts as its fan triangles, the same count for both).
//
// Files:
//   - a generated torus (core/generate.h; default 1000 x 750, 1.5M faces, change with
//     PAPERCRAFT_LOAD_TORUS=SEGMENTSxTUBE_SEGMENTS), written once to a temporary binary PLY,
//     ascii OFF and GLB (float positions, 32-bit indices, as exporters write a large mesh) and
//     removed at exit; the GLB has no plain OpenMesh reader, so the summary sets it against the
//     binary PLY of the same mesh, both through load_mesh;
//   - every *.off in the folder named by PAPERCRAFT_MESHES (sorted by name), one benchmark
//     pair per file. Files load_mesh refuses are not registered; they are counted and listed
//     with their messages in the summary.
// Each file gets "load/<file>" (ours) and "openmesh/<file>" (plain reader).
//
//   PAPERCRAFT_MESHES=$(bench/cgal_meshes.sh) build/bench/load_bench
//   build/bench/load_bench --benchmark_filter=torus --benchmark_repetitions=3
//
// With the console format (the default) a summary follows the table: per file faces/s of both
// and the ratio ours/plain of the wall time per load, then over the PAPERCRAFT_MESHES files the
// median faces/s, median ratio, and total faces / total seconds. With
// --benchmark_format=json|csv the summary is left out. Several repetitions: the median time of
// the repetitions is used.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/generate.h"
#include "core/mesh.h"
#include "nodes/load/openmesh.h"

namespace papercraft {
namespace {

namespace fs = std::filesystem;

struct BenchFile {
  std::string label;  // file name shown in the benchmark name
  fs::path path;
  std::size_t faces = 0;  // triangles after load_mesh
  bool generated = false;
};

struct Failure {
  std::string file;
  std::string message;
};

std::vector<BenchFile> g_files;
std::vector<Failure> g_failures;
fs::path g_temporary_dir;
bool g_min_time_given = false;

void load_ours(benchmark::State& state, const BenchFile& file) {
  for (auto _ : state) {
    LoadedMesh loaded = load_mesh(file.path);
    benchmark::DoNotOptimize(loaded.mesh.n_faces());
  }
  state.counters["faces"] = static_cast<double>(file.faces);
  state.counters["faces/s"] =
      benchmark::Counter(static_cast<double>(file.faces) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

void load_plain(benchmark::State& state, const BenchFile& file) {
  for (auto _ : state) {
    Mesh mesh;
    if (!OpenMesh::IO::read_mesh(mesh, file.path.string())) {
      state.SkipWithError("OpenMesh::IO::read_mesh failed");
      break;
    }
    benchmark::DoNotOptimize(mesh.n_faces());
  }
  state.counters["faces"] = static_cast<double>(file.faces);
  state.counters["faces/s"] =
      benchmark::Counter(static_cast<double>(file.faces) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

// Checks that load_mesh accepts the file (recording its triangle count) and registers the pair.
void add_file(BenchFile file) {
  try {
    file.faces = load_mesh(file.path).mesh.n_faces();
  } catch (const std::exception& error) {
    std::string message = error.what();
    const std::string prefix = file.path.string() + ": ";
    if (message.compare(0, prefix.size(), prefix) == 0) message.erase(0, prefix.size());
    g_failures.push_back({file.label, message});
    return;
  }
  g_files.push_back(file);  // RegisterBenchmark copies `file` into the benchmark
  // Generated files are large: a longer minimum time; the CGAL files are small: a short one.
  // --benchmark_min_time on the command line replaces both.
  auto configure = [&](benchmark::internal::Benchmark* bench) {
    bench->Unit(benchmark::kMillisecond)->UseRealTime();
    if (!g_min_time_given) bench->MinTime(file.generated ? 2.0 : 0.2);
  };
  configure(benchmark::RegisterBenchmark(("load/" + file.label).c_str(), load_ours, file));
  if (file.path.extension() != ".glb")
    configure(benchmark::RegisterBenchmark(("openmesh/" + file.label).c_str(), load_plain, file));
}

// A GLB of `mesh` (one node, one indexed triangle primitive), written by hand: the JSON chunk
// and the binary chunk, each padded to 4 bytes.
bool write_glb(const Mesh& mesh, const fs::path& path) {
  std::string bin;
  auto put = [&bin](const void* data, std::size_t size) {
    bin.append(static_cast<const char*>(data), size);
  };
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
    put(xyz, sizeof xyz);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], double(xyz[k]));
      hi[k] = std::max(hi[k], double(xyz[k]));
    }
  }
  const std::size_t positions = bin.size();
  for (auto f : mesh.faces())
    for (auto v : f.vertices()) {
      const std::uint32_t index = static_cast<std::uint32_t>(v.idx());
      put(&index, sizeof index);
    }
  const std::size_t indices = bin.size() - positions;
  char json[2048];
  std::snprintf(
      json, sizeof json,
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
      "\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},"
      "\"indices\":1}]}],\"buffers\":[{\"byteLength\":%zu}],\"bufferViews\":["
      "{\"buffer\":0,\"byteOffset\":0,\"byteLength\":%zu,\"target\":34962},"
      "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu,\"target\":34963}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":%zu,\"type\":\"VEC3\","
      "\"min\":[%.9g,%.9g,%.9g],\"max\":[%.9g,%.9g,%.9g]},"
      "{\"bufferView\":1,\"componentType\":5125,\"count\":%zu,\"type\":\"SCALAR\"}]}",
      bin.size(), positions, positions, indices, mesh.n_vertices(), lo[0], lo[1], lo[2], hi[0],
      hi[1], hi[2], indices / 4);
  std::string text = json;
  text.resize((text.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  std::FILE* out = std::fopen(path.c_str(), "wb");
  if (!out) return false;
  auto word = [out](std::uint32_t w) { std::fwrite(&w, 4, 1, out); };
  word(0x46546C67);  // "glTF"
  word(2);
  word(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  word(static_cast<std::uint32_t>(text.size()));
  word(0x4E4F534A);  // "JSON"
  std::fwrite(text.data(), 1, text.size(), out);
  word(static_cast<std::uint32_t>(bin.size()));
  word(0x004E4942);  // "BIN"
  std::fwrite(bin.data(), 1, bin.size(), out);
  return std::fclose(out) == 0;
}

void generate_files() {
  int segments = 1000, tube_segments = 750;
  if (const char* spec = std::getenv("PAPERCRAFT_LOAD_TORUS")) {
    if (std::sscanf(spec, "%dx%d", &segments, &tube_segments) != 2) {
      std::fprintf(stderr, "PAPERCRAFT_LOAD_TORUS=%s: expected SEGMENTSxTUBE_SEGMENTS\n", spec);
      std::exit(2);
    }
  }
  TorusOptions options;
  options.segments = segments;
  options.tube_segments = tube_segments;
  const Mesh mesh = to_mesh(torus(options));
  g_temporary_dir =
      fs::temp_directory_path() / ("papercraft_load_bench_" + std::to_string(::getpid()));
  fs::create_directories(g_temporary_dir);
  const std::string stem = "torus_" + std::to_string(mesh.n_faces());
  // Binary PLY (float coordinates) and ascii OFF with enough digits to round-trip a float.
  const fs::path ply = g_temporary_dir / (stem + ".ply");
  const fs::path off = g_temporary_dir / (stem + ".off");
  if (!OpenMesh::IO::write_mesh(mesh, ply.string(), OpenMesh::IO::Options::Binary) ||
      !OpenMesh::IO::write_mesh(mesh, off.string(), OpenMesh::IO::Options::Default, 9)) {
    std::fprintf(stderr, "cannot write the generated torus to %s\n", g_temporary_dir.c_str());
    std::exit(1);
  }
  const fs::path glb = g_temporary_dir / (stem + ".glb");
  if (!write_glb(mesh, glb)) {
    std::fprintf(stderr, "cannot write the generated torus to %s\n", glb.c_str());
    std::exit(1);
  }
  add_file({"generated/" + stem + ".ply", ply, 0, true});
  add_file({"generated/" + stem + ".off", off, 0, true});
  add_file({"generated/" + stem + ".glb", glb, 0, true});
}

void add_mesh_folder() {
  const char* folder = std::getenv("PAPERCRAFT_MESHES");
  if (!folder || !*folder) return;
  std::vector<fs::path> paths;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    std::string extension = entry.path().extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
    if (entry.is_regular_file() && extension == ".off") paths.push_back(entry.path());
  }
  if (error) {
    std::fprintf(stderr, "PAPERCRAFT_MESHES=%s: %s\n", folder, error.message().c_str());
    std::exit(2);
  }
  std::sort(paths.begin(), paths.end());
  for (const fs::path& path : paths) add_file({path.filename().string(), path, 0, false});
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The console table, then the summary (ours vs plain per file and over the folder's files).
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  explicit SummaryReporter(OutputOptions options) : ConsoleReporter(options) {}

  void ReportRuns(const std::vector<Run>& reports) override {
    ConsoleReporter::ReportRuns(reports);
    for (const Run& run : reports) {
      if (run.run_type != Run::RT_Iteration || run.error_occurred || run.iterations == 0) continue;
      seconds_[run.run_name.function_name].push_back(run.real_accumulated_time /
                                                     static_cast<double>(run.iterations));
    }
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    std::FILE* out = stdout;
    std::fprintf(out,
                 "\nload_mesh (ours) vs OpenMesh::IO::read_mesh (plain), wall time per load\n");
    std::fprintf(out, "%-40s %10s %12s %12s %12s %8s\n", "file", "faces", "ours ms", "ours Mf/s",
                 "plain Mf/s", "ratio");
    std::vector<double> ours_rates, plain_rates, ratios;
    double ours_total = 0, plain_total = 0, faces_total = 0;
    int measured = 0;
    for (const BenchFile& file : g_files) {
      const auto ours = seconds_.find("load/" + file.label);
      const auto plain = seconds_.find("openmesh/" + file.label);
      if (ours == seconds_.end() || plain == seconds_.end()) continue;  // filtered out
      const double t_ours = median(ours->second), t_plain = median(plain->second);
      const double faces = static_cast<double>(file.faces);
      std::fprintf(out, "%-40s %10zu %12.3f %12.3f %12.3f %8.2f\n", file.label.c_str(), file.faces,
                   1e3 * t_ours, faces / t_ours / 1e6, faces / t_plain / 1e6, t_ours / t_plain);
      if (file.generated) continue;
      ++measured;
      ours_rates.push_back(faces / t_ours);
      plain_rates.push_back(faces / t_plain);
      ratios.push_back(t_ours / t_plain);
      ours_total += t_ours;
      plain_total += t_plain;
      faces_total += faces;
    }
    // A scene format against the binary PLY of the same mesh, both through load_mesh.
    for (const BenchFile& file : g_files) {
      if (file.path.extension() != ".glb") continue;
      fs::path ply_label = file.label;
      ply_label.replace_extension(".ply");
      const auto glb = seconds_.find("load/" + file.label);
      const auto ply = seconds_.find("load/" + ply_label.string());
      if (glb == seconds_.end() || ply == seconds_.end()) continue;
      const double t_glb = median(glb->second), t_ply = median(ply->second);
      std::fprintf(out, "%s: %.3f ms, the binary PLY of the same mesh %.3f ms; ratio %.2f\n",
                   file.label.c_str(), 1e3 * t_glb, 1e3 * t_ply, t_glb / t_ply);
    }
    if (measured > 0) {
      std::fprintf(out,
                   "\n%d mesh files measured (%.0f faces in all)\n"
                   "  median faces/s: ours %.3f M, plain %.3f M; median ratio ours/plain %.2f\n"
                   "  total faces / total seconds: ours %.3f M/s (%.3f s), plain %.3f M/s "
                   "(%.3f s); ratio %.2f\n",
                   measured, faces_total, median(ours_rates) / 1e6, median(plain_rates) / 1e6,
                   median(ratios), faces_total / ours_total / 1e6, ours_total,
                   faces_total / plain_total / 1e6, plain_total, ours_total / plain_total);
    }
    std::fprintf(out, "%zu files refused by load_mesh (not benchmarked)%s\n", g_failures.size(),
                 g_failures.empty() ? "" : ":");
    for (const Failure& failure : g_failures) {
      std::string message = failure.message;
      if (message.size() > 160) message = message.substr(0, 157) + "...";
      std::fprintf(out, "  %s: %s\n", failure.file.c_str(), message.c_str());
    }
    std::fflush(out);
  }

 private:
  std::map<std::string, std::vector<double>> seconds_;
};

}  // namespace
}  // namespace papercraft

int main(int argc, char** argv) {
  using namespace papercraft;
  bool console = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--benchmark_format=", 19) == 0 &&
        std::strcmp(argv[i] + 19, "console") != 0) {
      console = false;
    }
    if (std::strncmp(argv[i], "--benchmark_min_time=", 21) == 0) g_min_time_given = true;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  generate_files();
  add_mesh_folder();
  if (console) {
    const char* term = std::getenv("TERM");
    const bool color = ::isatty(STDOUT_FILENO) && term && std::strcmp(term, "dumb") != 0;
    SummaryReporter reporter(color ? benchmark::ConsoleReporter::OO_ColorTabular
                                   : benchmark::ConsoleReporter::OO_Tabular);
    benchmark::RunSpecifiedBenchmarks(&reporter);
  } else {
    benchmark::RunSpecifiedBenchmarks();
  }
  benchmark::Shutdown();
  std::error_code ignored;
  if (!g_temporary_dir.empty()) fs::remove_all(g_temporary_dir, ignored);
  return 0;
}
