#include "nodes/proxy/decimate.h"

#include <spdlog/spdlog.h>

#include <OpenMesh/Core/Geometry/QuadricT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <chrono>
#include <cmath>

#include "core/errors.h"
#include "nodes/hausdorff/bounded.h"

namespace papercraft {

namespace {

// Garland-Heckbert quadrics divided by the area they gather: the priority of a collapse is the
// area-weighted mean squared distance of the kept vertex to the planes of the input faces
// merged into it, and a collapse is illegal when that exceeds bound^2. OpenMesh's ModQuadric
// sums area * distance^2, which is no length; this is one, and as cheap.
template <class MeshT>
class ModMeanPlaneDistanceT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ModMeanPlaneDistanceT, MeshT, MeanPlaneDistance);

  explicit ModMeanPlaneDistanceT(MeshT& mesh) : Base(mesh, false) {
    mesh.add_property(quadrics_);
    mesh.add_property(areas_);
  }
  ~ModMeanPlaneDistanceT() override {
    Base::mesh().remove_property(quadrics_);
    Base::mesh().remove_property(areas_);
  }

  void set_bound(double bound) { max_error_ = bound * bound; }

  void initialize() override {
    MeshT& mesh = Base::mesh();
    for (auto v : mesh.vertices()) {
      mesh.property(quadrics_, v).clear();
      mesh.property(areas_, v) = 0.0;
    }
    for (auto f : mesh.faces()) {
      auto h = mesh.halfedge_handle(f);
      const auto v0 = mesh.to_vertex_handle(h);
      const auto v1 = mesh.to_vertex_handle(mesh.next_halfedge_handle(h));
      const auto v2 = mesh.from_vertex_handle(h);
      const OpenMesh::Vec3d p0 = mesh.point(v0), p1 = mesh.point(v1), p2 = mesh.point(v2);
      OpenMesh::Vec3d n = (p1 - p0) % (p2 - p0);
      const double twice_area = n.norm();
      if (!(twice_area > 0.0)) continue;
      n /= twice_area;
      OpenMesh::Geometry::Quadricd q(n[0], n[1], n[2], -(p0 | n));
      const double area = 0.5 * twice_area;
      q *= area;
      for (auto v : {v0, v1, v2}) {
        mesh.property(quadrics_, v) += q;
        mesh.property(areas_, v) += area;
      }
    }
  }

  float collapse_priority(const CollapseInfo& ci) override {
    MeshT& mesh = Base::mesh();
    OpenMesh::Geometry::Quadricd q = mesh.property(quadrics_, ci.v0);
    q += mesh.property(quadrics_, ci.v1);
    const double area = mesh.property(areas_, ci.v0) + mesh.property(areas_, ci.v1);
    const double error = area > 0.0 ? std::max(0.0, q(ci.p1)) / area : 0.0;
    return error <= max_error_ ? static_cast<float>(error)
                               : static_cast<float>(Base::ILLEGAL_COLLAPSE);
  }

  void postprocess_collapse(const CollapseInfo& ci) override {
    MeshT& mesh = Base::mesh();
    mesh.property(quadrics_, ci.v1) += mesh.property(quadrics_, ci.v0);
    mesh.property(areas_, ci.v1) += mesh.property(areas_, ci.v0);
  }

 private:
  double max_error_ = 0.0;
  OpenMesh::VPropHandleT<OpenMesh::Geometry::Quadricd> quadrics_;
  OpenMesh::VPropHandleT<double> areas_;
};

// The mesh the decimater works on: ours, with OpenMesh's halfedge collapse test done without
// the temporary property OpenMesh 9 allocates on every call (a third of the decimation's time).
// The decimater template calls this is_collapse_ok, which hides the base class's.
struct DecimationMesh : Mesh {
  explicit DecimationMesh(const Mesh& mesh) : Mesh(mesh) {}

  // The link condition (Dey et al. 1999) and OpenMesh's boundary rules
  // (TriConnectivity::is_collapse_ok).
  bool is_collapse_ok(OpenMesh::HalfedgeHandle v0v1) {
    if (status(edge_handle(v0v1)).deleted()) return false;
    const OpenMesh::HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
    const OpenMesh::VertexHandle v0 = to_vertex_handle(v1v0);
    const OpenMesh::VertexHandle v1 = to_vertex_handle(v0v1);
    if (status(v0).deleted() || status(v1).deleted()) return false;
    // The vertex opposite a halfedge (invalid on the boundary); false when both other edges
    // of its triangle are on the boundary (the collapse would leave a dangling edge).
    const auto opposite = [this](OpenMesh::HalfedgeHandle h, OpenMesh::VertexHandle& vertex) {
      if (is_boundary(h)) return true;
      const auto h1 = next_halfedge_handle(h);
      vertex = to_vertex_handle(h1);
      return !(is_boundary(opposite_halfedge_handle(h1)) &&
               is_boundary(opposite_halfedge_handle(next_halfedge_handle(h1))));
    };
    OpenMesh::VertexHandle vl, vr;
    if (!opposite(v0v1, vl) || !opposite(v1v0, vr)) return false;
    if (vl == vr) return false;
    if (is_boundary(v0) && is_boundary(v1) && !is_boundary(v0v1) && !is_boundary(v1v0))
      return false;
    for (auto v : vv_range(v0)) status(v).set_tagged(false);
    for (auto v : vv_range(v1)) status(v).set_tagged(true);
    for (auto v : vv_range(v0))
      if (status(v).tagged() && v != vl && v != vr) return false;
    return true;
  }
};

// Collapses in order of the mean plane distance while it stays under `bound`; boundary
// vertices stay.
Mesh decimated(const Mesh& input, double bound) {
  DecimationMesh mesh(input);
  mesh.request_face_normals();
  mesh.update_face_normals();
  for (auto v : mesh.vertices()) mesh.status(v).set_locked(mesh.is_boundary(v));
  {
    OpenMesh::Decimater::DecimaterT<DecimationMesh> decimater(mesh);
    ModMeanPlaneDistanceT<DecimationMesh>::Handle distance;
    OpenMesh::Decimater::ModNormalFlippingT<DecimationMesh>::Handle flipping;
    decimater.add(distance);
    decimater.add(flipping);
    decimater.module(distance).set_bound(bound);
    decimater.module(flipping).set_max_normal_deviation(60.0);
    if (!decimater.initialize()) throw InternalError("certified_decimation: decimater refused");
    decimater.decimate();
  }
  for (auto v : mesh.vertices()) mesh.status(v).set_locked(false);
  mesh.garbage_collection();
  mesh.release_face_normals();
  return std::move(static_cast<Mesh&>(mesh));
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
  const TriangleBvh input_tree(to_triangle_mesh(input));
  const int input_euler = euler_characteristic(input);
  const std::size_t input_loops = boundary_loops(input).size();
  double bound = options.decimation_share * e;
  for (int attempt = 0; attempt < options.attempts; ++attempt, bound *= 0.5) {
    const auto decimation_start = std::chrono::steady_clock::now();
    Mesh mesh = decimated(input, bound);
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
