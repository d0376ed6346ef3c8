// End to end: generated shapes through the real default pipeline; every output certified
// against an independent brute-force Hausdorff (tests/support/brute_force_hausdorff.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <string>

#include "core/generate.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "support/certified_output.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::expect_certified;
using testing::run_pipeline;

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

// A plus-shaped slab (libcgal-demo's cross.off, rebuilt): flat faces meeting at right
// angles. The refinement once peeled thin layers off the side that already fitted, again
// and again, leaving 60 strips and triangles of 1e-12 that rounding mirrored.
TriangleMesh plus_slab() {
  TriangleMesh mesh;
  const double a = 0.1, b = 0.5, h = 0.1;  // arm half-width, arm reach, half-thickness
  const std::vector<Vec2> outline = {{a, -a}, {b, -a}, {b, a},   {a, a},   {a, b},   {-a, b},
                                     {-a, a}, {-b, a}, {-b, -a}, {-a, -a}, {-a, -b}, {a, -b}};
  const int n = static_cast<int>(outline.size());
  for (double z : {-h, h})
    for (const Vec2& p : outline) mesh.vertices.emplace_back(p.x(), p.y(), z);
  // Caps: the centre square (the concave corners 0, 3, 6, 9) and one rectangle per arm.
  const std::vector<std::array<int, 4>> quads = {
      {0, 3, 6, 9}, {0, 1, 2, 3}, {3, 4, 5, 6}, {6, 7, 8, 9}, {9, 10, 11, 0}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({n + q[0], n + q[1], n + q[2]});  // top, counter-clockwise
    mesh.triangles.push_back({n + q[0], n + q[2], n + q[3]});
    mesh.triangles.push_back({q[0], q[2], q[1]});  // bottom, facing down
    mesh.triangles.push_back({q[0], q[3], q[2]});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.triangles.push_back({i, j, n + j});
    mesh.triangles.push_back({i, n + j, n + i});
  }
  return mesh;
}

TEST(Approximation, SharpSlabNeedsFewStripsAndNoSlivers) {
  const TriangleMesh mesh = plus_slab();
  const auto out = run_pipeline(mesh, "2%", "plus_slab");
  expect_certified(mesh, out);
  EXPECT_LE(out.strips.size(), 24u);
  const double tau = out.report.at("tolerance").at("absolute").get<double>();
  double shortest = std::numeric_limits<double>::infinity();
  for (const TriangleMesh& strip : out.strips)
    for (const Triangle& t : strip.triangles) {
      double longest = 0.0;
      for (int i = 0; i < 3; ++i)
        longest = std::max(longest, (strip.vertices[t[(i + 1) % 3]] - strip.vertices[t[i]]).norm());
      shortest = std::min(shortest, longest);
    }
  EXPECT_GE(shortest, 1e-3 * tau) << "a sliver far below the tolerance";
}

// segment.feature and segment.fuzzy judge parts by the strips the refinement makes with the
// options of the configured select, ruled, hausdorff and cut nodes (NodeContext::refine).
TEST(Approximation, TheConfiguredRefinementReachesTheEngine) {
  const Registry& registry = builtin_registry();
  const Pipeline defaults(parse_pipeline_config(default_config_text(), "default.yaml", registry),
                          registry);
  const RefineOptions engine;
  const RefineOptions configured = defaults.refine_options();
  EXPECT_EQ(configured.cut.search_steps, engine.cut.search_steps);
  EXPECT_EQ(configured.cut.cut.cut.snap_fraction, engine.cut.cut.cut.snap_fraction);
  EXPECT_EQ(configured.cut.cut.harmonic.clamp_negative_weights,
            engine.cut.cut.harmonic.clamp_negative_weights);
  EXPECT_EQ(configured.decide.bounded.precision, engine.decide.bounded.precision);
  EXPECT_EQ(configured.max_depth, engine.max_depth);
  EXPECT_FALSE(configured.select.exhaustive);
  EXPECT_FALSE(configured.decide.sampled);

  const Pipeline tuned(parse_pipeline_config(R"(
nodes:
  load:      {impl: load.openmesh,     to: [segment]}
  segment:   {impl: segment.feature,   to: [select]}
  select:    {impl: select.exhaustive, params: {precision: 0.1}, to: [ruled]}
  ruled:     {impl: ruled.twist_dp,    params: {ruling_length_weight: 0.001}, to: [hausdorff]}
  hausdorff: {impl: hausdorff.sampled, params: {face_samples: 5000}, to: {accept: [unfold], reject: [cut]}}
  cut:       {impl: cut.harmonic,      params: {search_steps: 2, max_depth: 9}, back: [select]}
  unfold:    {impl: unfold.sequential, to: [merge]}
  merge:     {impl: merge.none}
)",
                                             "tuned.yaml", registry),
                       registry);
  const RefineOptions options = tuned.refine_options();
  EXPECT_TRUE(options.select.exhaustive);
  EXPECT_EQ(options.select.precision, 0.1);
  EXPECT_EQ(options.twist.ruling_length_weight, 0.001);
  EXPECT_TRUE(options.decide.sampled);
  EXPECT_EQ(options.decide.sampling.face_samples, 5000u);
  EXPECT_EQ(options.cut.search_steps, 2);
  EXPECT_EQ(options.max_depth, 9);
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
