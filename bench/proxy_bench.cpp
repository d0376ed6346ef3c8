// The proxy stage on real meshes: for each file, load (load_mesh), decimate and certify
// (certified_decimation, nodes/proxy/decimate.h) at a tolerance relative to the largest side;
// prints input faces, proxy faces, the certified distance, the seconds of each step and the
// one-sided certified distances with a small error bound (how tight the decision was).
//
//   build/bench/proxy_bench [--tolerance 0.02] [--share 0.2] MESH...

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "engine/hausdorff/bounded.h"
#include "nodes/load/openmesh.h"
#include "nodes/proxy/decimate.h"

namespace {

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace papercraft;
  double relative = 0.02;
  ProxyDecimateOptions options;
  options.min_faces = 0;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--tolerance" && i + 1 < argc) {
      relative = std::atof(argv[++i]);
    } else if (arg == "--share" && i + 1 < argc) {
      options.distance_share = std::atof(argv[++i]);
    } else {
      files.push_back(arg);
    }
  }
  if (std::getenv("VERBOSE")) spdlog::set_level(spdlog::level::debug);
  std::printf("%-24s %9s %8s %9s %8s %8s %9s %9s\n", "mesh", "faces", "proxy", "e/tau", "load_s",
              "proxy_s", "h(p,in)", "h(in,p)");
  for (const std::string& file : files) {
    auto start = std::chrono::steady_clock::now();
    const LoadedMesh loaded = load_mesh(file, {});
    const double load_seconds = since(start);
    const TriangleMesh input = to_triangle_mesh(loaded.mesh);
    const auto box = bounding_box(input.vertices);
    const double tau = relative * (box[1] - box[0]).maxCoeff();
    start = std::chrono::steady_clock::now();
    const CertifiedProxy proxy = certified_decimation(loaded.mesh, tau, options);
    const double proxy_seconds = since(start);
    double forward = 0.0, backward = 0.0;
    if (proxy.used) {
      const TriangleBvh proxy_tree(to_triangle_mesh(proxy.mesh));
      const TriangleBvh input_tree(input);
      forward =
          certified_one_sided_hausdorff_distance(proxy_tree.mesh(), input_tree, 0.01 * tau).upper;
      backward = certified_one_sided_hausdorff_distance(input, proxy_tree, 0.01 * tau).upper;
    }
    if (std::getenv("VERBOSE")) spdlog::set_level(spdlog::level::debug);
    std::printf("%-24s %9zu %8zu %9.3f %8.2f %8.2f %9.3f %9.3f  %s\n",
                file.substr(file.find_last_of('/') + 1).c_str(), input.triangles.size(),
                proxy.used ? proxy.mesh.n_faces() : 0, proxy.distance_bound / tau, load_seconds,
                proxy_seconds, forward / tau, backward / tau, proxy.reason.c_str());
  }
  return 0;
}
