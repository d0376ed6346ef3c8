// Certified Hausdorff decision and distance against CGAL's bounded-error Hausdorff distance.
//
// Pair: mesh A (PAPERCRAFT_HAUSDORFF_MESH, an OFF/OBJ/PLY file, else a generated bumpy torus
// of 20k triangles) and B = A decimated to a quarter of its vertices (OpenMesh quadric
// decimater), the shape of a coarse approximation. H is measured once (our value mode,
// error bound 1e-4 H). Everything runs on one thread unless the name says otherwise.
//
//   build-bench/bench/hausdorff_bench                       # all benchmarks
//   PAPERCRAFT_HAUSDORFF_MESH=dragon.off build-bench/bench/hausdorff_bench --summary
//
// --summary prints one-shot timings of the acceptance criterion instead: our decision at
// tau = 2H vs CGAL's value at error bound 0.05 tau, their ratio, and whether the values agree.
//
// --pairs [--tolerance 2%] MESH...: the same criterion on real (part, strip) pairs. Runs the
// default pipeline on each mesh with its hausdorff stage swapped for a recording node (same
// decision, it keeps a copy of every pair it is asked about), then times, per pair with
// H > 1e-6 of the part's diagonal (else the strip is the part up to rounding), our decision
// at tau = 2H against CGAL's value at 0.05 tau; prints per mesh the sums, their ratio, the
// median and smallest per-pair ratio, and how many values agree.

#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/bvh.h"
#include "core/mesh.h"
#include "engine/hausdorff/bounded.h"
#include "engine/hausdorff/sampled.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "nodes/hausdorff/verdict_node.h"

#ifdef PAPERCRAFT_HAVE_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Surface_mesh.h>
#endif

namespace papercraft {
namespace {

Mesh bumpy_torus(int rings, int sides) {
  Mesh mesh;
  std::vector<Mesh::VertexHandle> handles;
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const double u = 2 * M_PI * i / rings, v = 2 * M_PI * j / sides;
      const double r = 0.3 + 0.02 * std::sin(7 * u) * std::cos(5 * v);
      handles.push_back(
          mesh.add_vertex(Mesh::Point((1 + r * std::cos(v)) * std::cos(u),
                                      (1 + r * std::cos(v)) * std::sin(u), r * std::sin(v))));
    }
  }
  auto at = [&](int i, int j) { return handles[(i % rings) * sides + (j % sides)]; };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return mesh;
}

struct Pair {
  TriangleMesh a, b;
  std::optional<TriangleBvh> tree_a, tree_b;
  double hausdorff = 0.0;  // midpoint of a tight certified interval
  std::string name;
};

const Pair& pair() {
  static const Pair instance = [] {
    Pair p;
    Mesh mesh;
    const char* path = std::getenv("PAPERCRAFT_HAUSDORFF_MESH");
    if (path && OpenMesh::IO::read_mesh(mesh, path)) {
      p.name = path;
    } else {
      mesh = bumpy_torus(100, 100);
      p.name = "bumpy torus";
    }
    mesh.triangulate();
    p.a = to_triangle_mesh(mesh);
    OpenMesh::Decimater::DecimaterT<Mesh> decimater(mesh);
    OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
    decimater.add(quadric);
    decimater.initialize();
    decimater.decimate_to(mesh.n_vertices() / 4);
    mesh.garbage_collection();
    p.b = to_triangle_mesh(mesh);
    p.tree_a.emplace(p.a);
    p.tree_b.emplace(p.b);
    const auto box = bounding_box(p.a.vertices);
    const double diagonal = (box[1] - box[0]).norm();
    const HausdorffResult coarse =
        certified_hausdorff_distance(*p.tree_a, *p.tree_b, 1e-2 * diagonal);
    const HausdorffResult tight =
        certified_hausdorff_distance(*p.tree_a, *p.tree_b, 1e-4 * coarse.upper);
    p.hausdorff = 0.5 * (tight.lower + tight.upper);
    std::fprintf(stderr, "%s: A %zu triangles, B %zu triangles, H in [%.6g, %.6g]\n",
                 p.name.c_str(), p.a.triangles.size(), p.b.triangles.size(), tight.lower,
                 tight.upper);
    return p;
  }();
  return instance;
}

void BM_BvhBuild(benchmark::State& state) {
  const Pair& p = pair();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  for (auto _ : state) benchmark::DoNotOptimize(TriangleBvh(p.a).node_count());
  state.counters["triangles"] = static_cast<double>(p.a.triangles.size());
}
BENCHMARK(BM_BvhBuild)->Unit(benchmark::kMillisecond);

void BM_ClosestPoint(benchmark::State& state) {
  const Pair& p = pair();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(p.tree_b->closest(p.a.vertices[i]).distance);
    if (++i == p.a.vertices.size()) i = 0;
  }
}
BENCHMARK(BM_ClosestPoint);

// Argument: tau as a percentage of H.
void BM_CertifiedWithin(benchmark::State& state) {
  const Pair& p = pair();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  const double tau = state.range(0) / 100.0 * p.hausdorff;
  HausdorffResult r;
  for (auto _ : state) r = certified_hausdorff_within(*p.tree_a, *p.tree_b, tau);
  state.counters["within"] = r.within;
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
}
BENCHMARK(BM_CertifiedWithin)->Arg(200)->Arg(110)->Arg(90)->Arg(50)->Unit(benchmark::kMillisecond);

void BM_CertifiedWithinFromMeshes(benchmark::State& state) {  // includes both tree builds
  const Pair& p = pair();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  for (auto _ : state)
    benchmark::DoNotOptimize(certified_hausdorff_within(p.a, p.b, 2 * p.hausdorff));
}
BENCHMARK(BM_CertifiedWithinFromMeshes)->Unit(benchmark::kMillisecond);

void BM_CertifiedWithinAllThreads(benchmark::State& state) {
  const Pair& p = pair();
  for (auto _ : state) {
    benchmark::DoNotOptimize(certified_hausdorff_within(*p.tree_a, *p.tree_b, 2 * p.hausdorff));
  }
}
BENCHMARK(BM_CertifiedWithinAllThreads)->Unit(benchmark::kMillisecond)->UseRealTime();

// Value mode at error bound 0.05 tau with tau = 2H, i.e. 0.1 H.
void BM_CertifiedDistance(benchmark::State& state) {
  const Pair& p = pair();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  HausdorffResult r;
  for (auto _ : state) r = certified_hausdorff_distance(*p.tree_a, *p.tree_b, 0.1 * p.hausdorff);
  state.counters["lower"] = r.lower;
  state.counters["upper"] = r.upper;
}
BENCHMARK(BM_CertifiedDistance)->Unit(benchmark::kMillisecond);

void BM_SampledWithin(benchmark::State& state) {
  const Pair& p = pair();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  for (auto _ : state)
    benchmark::DoNotOptimize(sampled_hausdorff_within(p.a, p.b, 2 * p.hausdorff));
}
BENCHMARK(BM_SampledWithin)->Unit(benchmark::kMillisecond);

#ifdef PAPERCRAFT_HAVE_CGAL
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

SurfaceMesh to_cgal(const TriangleMesh& mesh) {
  SurfaceMesh result;
  std::vector<SurfaceMesh::Vertex_index> handles;
  for (const Vec3& v : mesh.vertices) handles.push_back(result.add_vertex({v.x(), v.y(), v.z()}));
  for (const Triangle& t : mesh.triangles)
    result.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  return result;
}

struct CgalPair {
  SurfaceMesh a, b;
};

const CgalPair& cgal_pair() {
  static const CgalPair instance{to_cgal(pair().a), to_cgal(pair().b)};
  return instance;
}

double cgal_value(const SurfaceMesh& a, const SurfaceMesh& b, double error_bound) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  return PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(a, b, error_bound);
}

double cgal_value(double error_bound) {
  return cgal_value(cgal_pair().a, cgal_pair().b, error_bound);
}

void BM_CgalBoundedErrorDistance(benchmark::State& state) {
  const double error_bound = 0.1 * pair().hausdorff;
  double value = 0.0;
  for (auto _ : state) value = cgal_value(error_bound);
  state.counters["value"] = value;
}
BENCHMARK(BM_CgalBoundedErrorDistance)->Unit(benchmark::kMillisecond);

void BM_CgalIsHausdorffDistanceLarger(benchmark::State& state) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Pair& p = pair();
  for (auto _ : state) {
    benchmark::DoNotOptimize(PMP::is_Hausdorff_distance_larger<CGAL::Sequential_tag>(
        cgal_pair().a, cgal_pair().b, 2 * p.hausdorff, 0.1 * p.hausdorff,
        CGAL::parameters::use_one_sided_hausdorff(false)));
  }
}
BENCHMARK(BM_CgalIsHausdorffDistanceLarger)->Unit(benchmark::kMillisecond);
#endif

template <class F>
double best_seconds(int repeats, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

int summary() {
  const Pair& p = pair();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  const double tau = 2 * p.hausdorff;
  HausdorffResult decision, value;
  const double ours =
      best_seconds(5, [&] { decision = certified_hausdorff_within(*p.tree_a, *p.tree_b, tau); });
  const double ours_value = best_seconds(
      5, [&] { value = certified_hausdorff_distance(*p.tree_a, *p.tree_b, 0.05 * tau); });
  std::printf("ours: decision at tau = 2H: within=%d upper=%.6g  %.2f ms (one thread)\n",
              decision.within, decision.upper, 1e3 * ours);
  std::printf("ours: value at error bound 0.05 tau: [%.6g, %.6g]  %.2f ms\n", value.lower,
              value.upper, 1e3 * ours_value);
#ifdef PAPERCRAFT_HAVE_CGAL
  double cgal = 0.0;
  const double cgal_seconds = best_seconds(3, [&] { cgal = cgal_value(0.05 * tau); });
  const bool agree = cgal >= value.lower - 0.05 * tau && cgal <= value.upper + 0.05 * tau;
  std::printf("CGAL: value at error bound 0.05 tau: %.6g  %.2f ms\n", cgal, 1e3 * cgal_seconds);
  std::printf("ratio CGAL value / our decision: %.1fx (target >= 5x); values agree: %s\n",
              cgal_seconds / ours, agree ? "yes" : "NO");
  return agree && cgal_seconds >= 5 * ours ? 0 : 1;
#else
  std::printf("CGAL not found at configure time: no comparison\n");
  return 0;
#endif
}

// --- real (part, strip) pairs from pipeline runs ---

struct RecordedPair {
  TriangleMesh part, strip;
};

struct Recorder {
  std::mutex mutex;
  std::vector<RecordedPair> pairs;
};

Recorder& recorder() {
  static Recorder instance;
  return instance;
}

/// hausdorff.bounded itself (same spec, parameters and body), plus a copy of every pair on
/// which it runs the Hausdorff decision (no holes left to split off, a strip with area).
void register_recording_node(Registry& registry) {
  NodeSpec spec = *builtin_registry().find("hausdorff.bounded");
  spec.name = "hausdorff.recording";
  spec.summary = "hausdorff.bounded that keeps every (part, strip) pair (benchmark only)";
  auto create_bounded = spec.create;
  spec.create = [create_bounded](const Params& params, const NodeContext& context) {
    std::shared_ptr<NodeBody> bounded = create_bounded(params, context);
    return make_body([bounded](const Envelope& in, Emitter& out) {
      const StripCandidate& candidate = in.get<StripCandidate>();
      if (candidate.candidate->holes.empty() && !candidate.strip->mesh.empty()) {
        TriangleMesh part = to_triangle_mesh(*candidate.candidate->part.mesh);
        if (surface_area(candidate.strip->mesh) > kDegenerateStripArea * surface_area(part)) {
          std::lock_guard lock(recorder().mutex);
          recorder().pairs.push_back({std::move(part), candidate.strip->mesh});
        }
      }
      bounded->process(in, out);
    });
  };
  registry.add(std::move(spec));
}

std::vector<RecordedPair> record_pairs(const std::filesystem::path& mesh,
                                       const std::string& tolerance) {
  static const Registry registry = [] {
    Registry r;
    register_builtin_nodes(r);
    register_recording_node(r);
    return r;
  }();
  // The default config with its hausdorff implementation swapped (same parameters).
  std::string text = default_config_text();
  const std::string from = "impl: hausdorff.bounded";
  const std::size_t at = text.find(from);
  if (at == std::string::npos) {
    std::fprintf(stderr, "the default config has no '%s'\n", from.c_str());
    std::exit(2);
  }
  text.replace(at, from.size(), "impl: hausdorff.recording");
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = parse_tolerance(tolerance);
  settings->output_dir = std::filesystem::temp_directory_path() / "papercraft-hausdorff-pairs";
  settings->config_text = text;
  Pipeline pipeline(parse_pipeline_config(text, "recording.yaml", registry), registry);
  PipelineOptions options;
  options.threads = 1;
  recorder().pairs.clear();
  const auto results = pipeline.run({mesh}, settings, options);
  if (!results.at(0).ok) std::fprintf(stderr, "%s: pipeline failed\n", mesh.c_str());
  return std::move(recorder().pairs);
}

int pairs_summary(const std::vector<std::string>& meshes, const std::string& tolerance) {
  spdlog::set_level(spdlog::level::warn);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  int failures = 0;
  double all_ours = 0.0, all_cgal = 0.0;
  std::vector<double> all_ratios;
  std::size_t all_pairs = 0, all_timed = 0;
  int all_agree = 0;
  auto print_row = [](const std::string& name, std::size_t pairs, std::size_t timed, double ours,
                      double cgal, std::vector<double> ratios, int agree) {
    std::sort(ratios.begin(), ratios.end());
    std::printf("%-14s %6zu %6zu %10.2f %10.2f %6.1fx %7.1fx %6.1fx %4d/%zu\n", name.c_str(), pairs,
                timed, 1e3 * ours, 1e3 * cgal, ours > 0 ? cgal / ours : 0.0,
                ratios.empty() ? 0.0 : ratios[ratios.size() / 2],
                ratios.empty() ? 0.0 : ratios.front(), agree, ratios.size());
    std::fflush(stdout);
  };
  std::printf("%-14s %6s %6s %10s %10s %7s %8s %7s %7s\n", "mesh", "pairs", "timed", "ours ms",
              "CGAL ms", "ratio", "median", "min", "agree");
  for (const std::string& path : meshes) {
    const std::vector<RecordedPair> pairs = record_pairs(path, tolerance);
    double ours_total = 0.0, cgal_total = 0.0;
    std::vector<double> ratios;
    std::size_t timed = 0;
    int agree = 0;
    for (const RecordedPair& p : pairs) {
      const TriangleBvh tree_a(p.part), tree_b(p.strip);
      const auto box = bounding_box(p.part.vertices);
      const double diagonal = (box[1] - box[0]).norm();
      const HausdorffResult coarse = certified_hausdorff_distance(tree_a, tree_b, 1e-2 * diagonal);
      const HausdorffResult tight =
          certified_hausdorff_distance(tree_a, tree_b, 1e-4 * std::max(coarse.upper, 1e-12));
      const double h = 0.5 * (tight.lower + tight.upper);
      // The strip is the part up to rounding (a flat part and its fan): nothing to decide, and
      // CGAL's subdivision at 0.05 tau of that runs out of memory.
      if (!(h > 1e-6 * diagonal)) continue;
      ++timed;
      const double tau = 2 * h;
      HausdorffResult decision, value;
      const double ours =
          best_seconds(3, [&] { decision = certified_hausdorff_within(tree_a, tree_b, tau); });
      value = certified_hausdorff_distance(tree_a, tree_b, 0.05 * tau);
      ours_total += ours;
#ifdef PAPERCRAFT_HAVE_CGAL
      const SurfaceMesh a = to_cgal(p.part), b = to_cgal(p.strip);
      double cgal = 0.0;
      const double cgal_seconds = best_seconds(3, [&] { cgal = cgal_value(a, b, 0.05 * tau); });
      cgal_total += cgal_seconds;
      ratios.push_back(cgal_seconds / ours);
      if (cgal_seconds < 5 * ours) {
        std::fprintf(
            stderr, "  under 5x: part %zu, strip %zu triangles: ours %.3f ms, CGAL %.3f ms\n",
            p.part.triangles.size(), p.strip.triangles.size(), 1e3 * ours, 1e3 * cgal_seconds);
      }
      agree += cgal >= value.lower - 0.05 * tau && cgal <= value.upper + 0.05 * tau;
#endif
      if (!decision.within) ++failures;  // at tau = 2H the decision must accept
    }
    print_row(std::filesystem::path(path).filename().string(), pairs.size(), timed, ours_total,
              cgal_total, ratios, agree);
    if (agree != static_cast<int>(ratios.size())) ++failures;
    all_pairs += pairs.size();
    all_timed += timed;
    all_ours += ours_total;
    all_cgal += cgal_total;
    all_agree += agree;
    all_ratios.insert(all_ratios.end(), ratios.begin(), ratios.end());
  }
  if (meshes.size() > 1) {
    print_row("all", all_pairs, all_timed, all_ours, all_cgal, all_ratios, all_agree);
  }
#ifndef PAPERCRAFT_HAVE_CGAL
  std::printf("CGAL not found at configure time: no comparison\n");
#endif
  return failures == 0 ? 0 : 1;
}

}  // namespace
}  // namespace papercraft

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--summary") == 0) return papercraft::summary();
    if (std::strcmp(argv[i], "--pairs") == 0) {
      std::string tolerance = "2%";
      std::vector<std::string> meshes;
      for (int j = i + 1; j < argc; ++j) {
        if (std::strcmp(argv[j], "--tolerance") == 0 && j + 1 < argc) {
          tolerance = argv[++j];
        } else {
          meshes.push_back(argv[j]);
        }
      }
      return papercraft::pairs_summary(meshes, tolerance);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
