#include "nodes/proxy/decimate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "core/generate.h"
#include "support/brute_force_hausdorff.h"

namespace papercraft {
namespace {

using testing::brute_force_hausdorff;
using testing::height_field;

double largest_side(const TriangleMesh& mesh) {
  const auto box = bounding_box(mesh.vertices);
  return (box[1] - box[0]).maxCoeff();
}

ProxyDecimateOptions always() {
  ProxyDecimateOptions options;
  options.min_faces = 0;
  return options;
}

// The certificate against an independent brute force: no sampled point of either surface is
// farther from the other than the certified bound, and the bound is within the share asked.
// Returns the decimations made.
int expect_certified_proxy(const TriangleMesh& input, double tolerance,
                           const ProxyDecimateOptions& options) {
  const Mesh mesh = to_mesh(input);
  const CertifiedProxy proxy = certified_decimation(mesh, tolerance, options);
  EXPECT_TRUE(proxy.used) << proxy.reason;
  if (!proxy.used) return proxy.attempts;
  EXPECT_LT(proxy.mesh.n_faces(), mesh.n_faces() / 2);
  EXPECT_GT(proxy.distance_bound, 0.0);
  EXPECT_LE(proxy.distance_bound, options.distance_share * tolerance);
  EXPECT_EQ(euler_characteristic(proxy.mesh), euler_characteristic(mesh));
  EXPECT_EQ(boundary_loops(proxy.mesh).size(), boundary_loops(mesh).size());
  const TriangleMesh simplified = to_triangle_mesh(proxy.mesh);
  const auto brute = brute_force_hausdorff(simplified, input, 2);
  EXPECT_LE(brute.distance, proxy.distance_bound * (1 + 1e-9))
      << "brute force found a point at " << brute.distance << " (side " << brute.side
      << ") beyond the certified bound " << proxy.distance_bound;
  EXPECT_GT(brute.distance, 0.05 * proxy.distance_bound) << "the bound is far from tight";
  return proxy.attempts;
}

TEST(CertifiedDecimation, SphereWithinTheShareOfTheTolerance) {
  const TriangleMesh input = sphere({.radius = 1.0, .subdivisions = 4});  // 5,120 faces
  ProxyDecimateOptions options = always();
  options.decimation_share = 0.5;
  expect_certified_proxy(input, 0.05 * 2.0, options);
}

TEST(CertifiedDecimation, NoisyHeightFieldKeepsItsBoundary) {
  const TriangleMesh input = height_field(
      50, [](double x, double y) { return 0.3 * std::sin(3 * x) * std::cos(2 * y); }, 0.0002, 7);
  expect_certified_proxy(input, 0.05 * largest_side(input), always());
}

TEST(CertifiedDecimation, TorusAtATightShareWithABoldDecimation) {
  const TriangleMesh input = torus({.segments = 96, .tube_segments = 40});  // 7,680 faces
  ProxyDecimateOptions options = always();
  options.distance_share = 0.1;
  options.decimation_share = 1.0;
  EXPECT_GT(expect_certified_proxy(input, 0.05 * largest_side(input), options), 1)
      << "the boldest decimation should fail the certificate and be made again";
}

TEST(CertifiedDecimation, SmallMeshesStayAsTheyAre) {
  const Mesh mesh = to_mesh(sphere({.radius = 1.0, .subdivisions = 3}));  // 1,280 faces
  ProxyDecimateOptions options;
  options.min_faces = 1281;
  const CertifiedProxy proxy = certified_decimation(mesh, 0.04, options);
  EXPECT_FALSE(proxy.used);
  EXPECT_EQ(proxy.attempts, 0);
  EXPECT_EQ(proxy.distance_bound, 0.0);
  EXPECT_NE(proxy.reason.find("min_faces"), std::string::npos) << proxy.reason;
}

TEST(CertifiedDecimation, TooLittleGainKeepsTheInput) {
  // A coarse torus at a tiny tolerance: hardly a collapse fits.
  const Mesh mesh = to_mesh(torus({.segments = 12, .tube_segments = 8}));
  const CertifiedProxy proxy = certified_decimation(mesh, 1e-6, always());
  EXPECT_FALSE(proxy.used);
  EXPECT_EQ(proxy.attempts, 1);
  EXPECT_NE(proxy.reason.find("max_face_share"), std::string::npos) << proxy.reason;
}

TEST(CertifiedDecimation, RefusesBadOptions) {
  const Mesh mesh = to_mesh(sphere({.radius = 1.0, .subdivisions = 1}));
  EXPECT_THROW(certified_decimation(mesh, 0.0, always()), InvalidInputException);
  ProxyDecimateOptions options = always();
  options.distance_share = 1.0;
  EXPECT_THROW(certified_decimation(mesh, 0.04, options), InvalidInputException);
}

}  // namespace
}  // namespace papercraft
