// The refinement engine (engine/refine/refine.h) against the graph: the engine's one-call
// refinement and its strip count must make exactly what the graph's select, ruled, hausdorff
// and cut nodes make of the same part, since the segmentation's estimates rely on it.

#include <gtest/gtest.h>

#include <climits>
#include <sstream>
#include <string>
#include <vector>

#include "core/generate.h"
#include "engine/refine/refine.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "nodes/load/openmesh.h"
#include "nodes/segment/feature.h"
#include "nodes/segment/none.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::run_pipeline;

// The graph without segmentation or merging, writing only the OBJ: what it makes of the input is
// the sum of what the refinement makes of each connected component.
constexpr const char* kRefinementOnly = R"(
nodes:
  load:      {impl: load.openmesh,     to: [segment]}
  segment:   {impl: segment.none,      to: [select]}
  select:    {impl: select.geodesic,   to: [ruled]}
  ruled:     {impl: ruled.twist_dp,    to: [hausdorff]}
  hausdorff: {impl: hausdorff.bounded, to: {accept: [unfold], reject: [cut]}}
  cut:       {impl: cut.harmonic,      back: [select]}
  unfold:    {impl: unfold.sequential, to: [merge]}
  merge:     {impl: merge.none,        to: [layout]}
  layout:    {impl: layout.pages,      to: [export]}
  export:    {impl: export.files,      params: {formats: [obj]}}
)";

RefineOptions configured_refinement() {
  const Registry& registry = builtin_registry();
  return Pipeline(parse_pipeline_config(kRefinementOnly, "engine.yaml", registry), registry)
      .refine_options();
}

struct GraphRun {
  int strips = -1;
  double tolerance = 0.0;  // absolute, as the graph used it
  PieceLimits limits;      // min_width_mm and min_area_mm2 in model units, as the graph used them
  Mesh loaded;             // the input as the graph's loader read it
};

// `mesh` through the graph at `tolerance`; also loads the file it wrote as the graph did.
GraphRun run_graph(const TriangleMesh& mesh, const std::string& tolerance, const std::string& name,
                   const PaperSpec& paper = {}) {
  const auto out = run_pipeline(mesh, tolerance, name, 1, kRefinementOnly, paper);
  GraphRun run;
  EXPECT_TRUE(out.result.ok) << out.result.error;
  if (!out.result.ok) return run;
  run.strips = out.report.at("result").at("strips_3d").get<int>();
  run.tolerance = out.report.at("tolerance").at("absolute").get<double>();
  const double scale = out.report.at("result").at("mm_per_unit").get<double>();
  run.limits.min_width = paper.min_width_mm / scale;
  run.limits.min_area = paper.min_area_mm2 / (scale * scale);
  run.loaded = load_mesh(out.dir.parent_path().parent_path() / (name + ".obj")).mesh;
  return run;
}

class EngineMatchesGraph : public ::testing::TestWithParam<std::string> {};

TEST_P(EngineMatchesGraph, SameStripCountOnEveryComponent) {
  const TriangleMesh mesh = generate_shape(GetParam(), {});
  const RefineOptions refine = configured_refinement();
  for (const char* tolerance : {"2%", "5%"}) {
    SCOPED_TRACE(GetParam() + " at " + tolerance);
    const GraphRun graph = run_graph(mesh, tolerance, GetParam());
    ASSERT_GT(graph.strips, 0);
    const RefineOptions at_graph = at_tolerance(refine, graph.tolerance);
    int counted = 0;
    std::size_t refined = 0;
    for (const Mesh& part : segment_none(graph.loaded)) {
      counted += count_strips(part, at_graph, INT_MAX - 1, graph.limits);
      const std::vector<RefinedStrip> strips = refine_part(part, at_graph, graph.limits);
      refined += strips.size();
      for (const RefinedStrip& strip : strips) {
        EXPECT_TRUE(strip.verdict.accept);
        EXPECT_LE(strip.verdict.upper_bound, graph.tolerance);
      }
    }
    EXPECT_EQ(counted, graph.strips);
    EXPECT_EQ(refined, static_cast<std::size_t>(graph.strips));
    // The cap: one below the count reports cap + 1, the count itself is exact.
    if (graph.strips > 1) {
      const Mesh whole = segment_none(graph.loaded).front();
      const int alone = count_strips(whole, at_graph, INT_MAX - 1, graph.limits);
      EXPECT_EQ(count_strips(whole, at_graph, alone - 1, graph.limits), alone);
      EXPECT_EQ(count_strips(whole, at_graph, alone, graph.limits), alone);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, EngineMatchesGraph,
                         ::testing::Values("open_cylinder", "cone_frustum", "sphere", "torus",
                                           "figure_eight", "pawn", "cylinder_two_holes", "box",
                                           "capped_cylinder", "dumbbell"));

// segment.feature keeps its parts only when the refinement makes fewer strips of them; each
// part's estimate must be what the graph then makes of that part.
TEST(EngineMatchesGraph, FeatureEstimateOfEachPartIsTheGraphsCount) {
  const RefineOptions refine = configured_refinement();
  for (const char* shape : {"box", "capped_cylinder", "pawn"}) {
    const TriangleMesh mesh = generate_shape(shape, {});
    // The graph's absolute tolerance for the whole shape at 2%.
    const GraphRun whole = run_graph(mesh, "2%", std::string(shape) + "_whole");
    ASSERT_GT(whole.strips, 0);
    Mesh tagged = whole.loaded;
    tag_input_vertices(tagged);
    const std::vector<Mesh> parts = segment_feature(tagged);
    SCOPED_TRACE(std::string(shape) + ": " + std::to_string(parts.size()) + " feature parts");
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const int estimate =
          count_strips(parts[i], at_tolerance(refine, whole.tolerance), INT_MAX - 1, whole.limits);
      const std::string name = std::string(shape) + "_part" + std::to_string(i);
      std::ostringstream absolute;
      absolute.precision(17);
      absolute << whole.tolerance;
      // The part printed at the whole shape's scale, so its pieces have the same limits.
      PaperSpec paper;
      paper.scale = paper.min_width_mm / whole.limits.min_width;
      const GraphRun graph = run_graph(to_triangle_mesh(parts[i]), absolute.str(), name, paper);
      EXPECT_EQ(graph.tolerance, whole.tolerance);
      EXPECT_NEAR(graph.limits.min_width, whole.limits.min_width, 1e-12 * whole.limits.min_width);
      EXPECT_EQ(estimate, graph.strips) << "part " << i;
    }
  }
}

}  // namespace
}  // namespace papercraft
