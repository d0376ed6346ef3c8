// End to end: generated shapes through the real default pipeline; every output certified
// against an independent brute-force Hausdorff (tests/support/brute_force_hausdorff.h).

#include <gtest/gtest.h>

#include "core/generate.h"
#include "support/brute_force_hausdorff.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::run_pipeline;

// Brute force never finds a distance above the reported bound, and the bound is <= tau.
void expect_certified(const TriangleMesh& input, const testing::PipelineOutput& out) {
  ASSERT_TRUE(out.result.ok) << out.result.error;
  const auto& result = out.report.at("result");
  EXPECT_TRUE(result.at("certified").get<bool>());
  const double bound = result.at("hausdorff_bound").get<double>();
  const double tau = out.report.at("tolerance").at("absolute").get<double>();
  EXPECT_LE(bound, tau);
  const TriangleMesh approximation = testing::concatenate(out.strips);
  ASSERT_FALSE(approximation.triangles.empty());
  const auto brute = testing::brute_force_hausdorff(input, approximation, 2);
  EXPECT_LE(brute.distance, bound * (1 + 1e-9) + 1e-12)
      << "brute force found a point at distance " << brute.distance << " (side " << brute.side
      << ") above the certified bound " << bound;
  EXPECT_EQ(static_cast<std::size_t>(result.at("strips_3d").get<long>()), out.strips.size());
}

TEST(Approximation, DevelopableSurfacesBecomeOneStrip) {
  const std::vector<std::pair<std::string, TriangleMesh>> shapes = {
      {"open_cylinder", open_cylinder()},
      {"elliptic_cylinder", elliptic_cylinder()},
      {"cone_frustum", cone_frustum()}};
  for (const auto& [name, mesh] : shapes) {
    SCOPED_TRACE(name);
    const auto out = run_pipeline(mesh, "1%", name);
    expect_certified(mesh, out);
    EXPECT_EQ(out.strips.size(), 1u);
  }
}

class Refinement : public ::testing::TestWithParam<std::string> {};

TEST_P(Refinement, CertifiedAndFewerStripsAtLargerTolerance) {
  const TriangleMesh mesh = generate_shape(GetParam(), {});
  std::vector<std::size_t> counts;
  for (const char* tolerance : {"1%", "2%", "5%"}) {
    SCOPED_TRACE(std::string(GetParam()) + " at " + tolerance);
    const auto out = run_pipeline(mesh, tolerance, GetParam());
    expect_certified(mesh, out);
    counts.push_back(out.strips.size());
  }
  EXPECT_GE(counts[0], counts[1]);
  EXPECT_GE(counts[1], counts[2]);
  EXPECT_GT(counts[0], counts[2]) << "5% must need fewer strips than 1%";
}

INSTANTIATE_TEST_SUITE_P(Shapes, Refinement,
                         ::testing::Values("sphere", "torus", "figure_eight", "pawn"));

TEST(Approximation, SameStripCountWithOneAndTwoThreads) {
  const TriangleMesh mesh = generate_shape("pawn", {});
  const auto one = run_pipeline(mesh, "2%", "pawn1", 1);
  const auto two = run_pipeline(mesh, "2%", "pawn2", 2);
  ASSERT_TRUE(one.result.ok && two.result.ok);
  EXPECT_EQ(one.strips.size(), two.strips.size());
  EXPECT_EQ(testing::read_text(one.dir / "approximation.obj"),
            testing::read_text(two.dir / "approximation.obj"))
      << "the output must not depend on thread timing";
}

TEST(Approximation, ToleranceBelowResolutionEndsWithAMessage) {
  const TriangleMesh mesh = generate_shape("sphere", {});
  const std::string config = R"(
nodes:
  load:      {impl: load.openmesh,     to: [segment]}
  segment:   {impl: segment.none,      to: [select]}
  select:    {impl: select.geodesic,   to: [ruled]}
  ruled:     {impl: ruled.twist_dp,    to: [hausdorff]}
  hausdorff: {impl: hausdorff.bounded, to: {accept: [unfold], reject: [cut]}}
  cut:       {impl: cut.harmonic,      params: {max_depth: 3}, back: [select]}
  unfold:    {impl: unfold.sequential, to: [merge]}
  merge:     {impl: merge.none,        to: [layout]}
  layout:    {impl: layout.pages,      to: [export]}
  export:    {impl: export.files}
)";
  const auto out = run_pipeline(mesh, "0.01%", "tiny", 0, config);
  EXPECT_FALSE(out.result.ok);
  EXPECT_NE(out.result.error.find("cannot be approximated within the tolerance"), std::string::npos)
      << out.result.error;
  EXPECT_FALSE(std::filesystem::exists(out.dir / "report.json"))
      << "a failed model leaves no half-written output";
}

}  // namespace
}  // namespace papercraft
