#include "nodes/proxy/decimate.h"

#include <spdlog/spdlog.h>

#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <chrono>
#include <cmath>

#include "core/errors.h"
#include "engine/hausdorff/bounded.h"
#include "nodes/proxy/collapse.h"

namespace papercraft {

namespace {

// Collapses in order of the mean plane distance while it stays under `bound`; boundary
// vertices stay (nodes/proxy/collapse.h). The kept vertices carry their input vertex index and
// texture coordinates over.
Mesh decimated(const Mesh& input, const TriangleMesh& triangles, double bound) {
  const CollapseDecimation decimation = collapse_decimation(triangles, bound, 60.0);
  Mesh mesh = to_mesh(decimation.mesh);
  OpenMesh::VPropHandleT<int> input_vertex;
  if (input.get_property_handle(input_vertex, kInputVertexProperty)) {
    auto kept = OpenMesh::getOrMakeProperty<OpenMesh::VertexHandle, int>(mesh, kInputVertexProperty);
    for (auto v : mesh.vertices())
      kept[v] = input.property(input_vertex,
                               OpenMesh::VertexHandle(decimation.source_vertex[v.idx()]));
  }
  if (input.has_vertex_texcoords2D()) {
    mesh.request_vertex_texcoords2D();
    for (auto v : mesh.vertices())
      mesh.set_texcoord2D(
          v, input.texcoord2D(OpenMesh::VertexHandle(decimation.source_vertex[v.idx()])));
  }
  spdlog::debug("certified_decimation: {} collapses in {} passes", decimation.collapses,
                decimation.passes);
  return mesh;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

CertifiedProxy certified_decimation(const Mesh& input, double tolerance,
                                    const ProxyDecimateOptions& options) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw InvalidInputException("certified_decimation: the tolerance must be positive");
  if (!(options.distance_share > 0.0 && options.distance_share < 1.0))
    throw InvalidInputException("certified_decimation: distance_share must be in (0, 1)");
  if (!(options.decimation_share > 0.0 && options.decimation_share <= 1.0))
    throw InvalidInputException("certified_decimation: decimation_share must be in (0, 1]");
  require_no_deleted_elements(input, "certified_decimation");
  CertifiedProxy proxy;
  if (input.n_faces() < options.min_faces) {
    proxy.reason = "the input has " + std::to_string(input.n_faces()) + " faces, fewer than " +
                   std::to_string(options.min_faces) + " (min_faces)";
    return proxy;
  }
  const double e = options.distance_share * tolerance;
  const TriangleMesh input_triangles = to_triangle_mesh(input);
  const TriangleBvh input_tree(input_triangles);
  const int input_euler = euler_characteristic(input);
  const std::size_t input_loops = boundary_loops(input).size();
  double bound = options.decimation_share * e;
  for (int attempt = 0; attempt < options.attempts; ++attempt, bound *= 0.5) {
    const auto decimation_start = std::chrono::steady_clock::now();
    Mesh mesh = decimated(input, input_triangles, bound);
    const double decimation_seconds = seconds_since(decimation_start);
    proxy.attempts = attempt + 1;
    if (static_cast<double>(mesh.n_faces()) >
        options.max_face_share * static_cast<double>(input.n_faces())) {
      proxy.reason = "the decimation keeps " + std::to_string(mesh.n_faces()) + " of " +
                     std::to_string(input.n_faces()) + " faces, more than max_face_share";
      return proxy;
    }
    // The link condition keeps the topology; this checks it did (the refinement's holes and
    // components must be the input's).
    if (euler_characteristic(mesh) != input_euler || boundary_loops(mesh).size() != input_loops) {
      proxy.reason = "the decimation changed the topology";
      continue;
    }
    const auto certification_start = std::chrono::steady_clock::now();
    const TriangleBvh proxy_tree(to_triangle_mesh(mesh));
    BoundedHausdorffOptions certify;
    certify.locate_maximum = false;
    // The distance to within a tenth of e (not just "<= e"): what is left of the tolerance
    // is what the refinement gets.
    const HausdorffResult result =
        certified_hausdorff_distance(proxy_tree, input_tree, 0.1 * e, certify);
    spdlog::debug(
        "certified_decimation: decimation bound {:.3g}: {} faces, H in [{:.3g}, {:.3g}] (e "
        "{:.3g}), "
        "witness on the {}, {} distance queries{}; {:.2f} s decimation, {:.2f} s certification",
        bound, mesh.n_faces(), result.lower, result.upper, e,
        result.witness.side == 0 ? "proxy" : "input", result.evaluations,
        result.certified ? "" : ", a cap tripped", decimation_seconds,
        seconds_since(certification_start));
    if (result.certified && result.upper <= e) {
      proxy.used = true;
      proxy.mesh = std::move(mesh);
      proxy.distance_bound = result.upper;
      proxy.reason.clear();
      return proxy;
    }
    proxy.reason = "no decimation within " + std::to_string(e) + " of the input was certified (" +
                   std::to_string(proxy.attempts) + " tried)";
  }
  return proxy;
}

}  // namespace papercraft
