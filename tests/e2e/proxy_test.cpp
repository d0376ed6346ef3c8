// End to end: the proxy stage. proxy.none (and proxy.decimate on a mesh under min_faces) gives
// exactly the output of a pipeline without the stage; with a proxy the bound in report.json
// is still a true bound on the original input (brute force), as it is without one.

#include <gtest/gtest.h>

#include <string>

#include "core/generate.h"
#include "graph/config.h"
#include "support/certified_output.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::expect_certified;
using testing::run_pipeline;

const std::string kProxyLine =
    "  proxy:     {impl: proxy.decimate,    params: {distance_share: 0.2, min_faces: 100000}, "
    "to: [segment]}\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "default.yaml lacks: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The default pipeline as it was before the proxy stage: load feeds segment.
std::string config_without_proxy() {
  return replaced(replaced(default_config_text(), kProxyLine, ""), "to: [proxy]}",
                  "to: [segment]}");
}

std::string config_with(const std::string& proxy_line) {
  return replaced(default_config_text(), kProxyLine, proxy_line);
}

void expect_same_output(const testing::PipelineOutput& a, const testing::PipelineOutput& b) {
  ASSERT_TRUE(a.result.ok) << a.result.error;
  ASSERT_TRUE(b.result.ok) << b.result.error;
  for (const char* file : {"approximation.obj", "strips.json", "pieces.json"}) {
    SCOPED_TRACE(file);
    EXPECT_EQ(testing::read_text(a.dir / file), testing::read_text(b.dir / file));
  }
  EXPECT_EQ(a.report.at("result").at("hausdorff_bound"),
            b.report.at("result").at("hausdorff_bound"));
}

class ProxyNone : public ::testing::TestWithParam<std::string> {};

TEST_P(ProxyNone, ReproducesThePipelineWithoutTheStage) {
  const TriangleMesh mesh = generate_shape(GetParam(), {});
  const auto before = run_pipeline(mesh, "2%", GetParam() + "_before", 0, config_without_proxy());
  const auto none = run_pipeline(mesh, "2%", GetParam() + "_none", 0,
                                 config_with("  proxy:     {impl: proxy.none, to: [segment]}\n"));
  const auto small = run_pipeline(mesh, "2%", GetParam() + "_small");  // under min_faces
  expect_same_output(before, none);
  expect_same_output(before, small);
  for (const auto* out : {&none, &small}) {
    const auto& proxy = out->report.at("proxy");
    EXPECT_FALSE(proxy.at("used").get<bool>());
    EXPECT_EQ(proxy.at("distance_bound").get<double>(), 0.0);
    EXPECT_EQ(out->report.at("result").at("strips_bound"),
              out->report.at("result").at("hausdorff_bound"));
  }
  EXPECT_EQ(none.report.at("proxy").at("method"), "none");
  EXPECT_EQ(small.report.at("proxy").at("method"), "decimate");
  EXPECT_NE(small.report.at("proxy").at("reason").get<std::string>().find("min_faces"),
            std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Shapes, ProxyNone, ::testing::Values("pawn", "torus", "figure_eight"));

std::string forced_proxy_config() {
  return config_with(
      "  proxy:     {impl: proxy.decimate, params: {distance_share: 0.2, decimation_share: 0.5, "
      "min_faces: 0}, to: [segment]}\n");
}

TEST(Proxy, SameOutputWithOneAndTwoThreads) {
  const TriangleMesh mesh = torus({.segments = 96, .tube_segments = 40});
  const auto one = run_pipeline(mesh, "5%", "torus1", 1, forced_proxy_config());
  const auto two = run_pipeline(mesh, "5%", "torus2", 2, forced_proxy_config());
  ASSERT_TRUE(one.report.at("proxy").at("used").get<bool>());
  expect_same_output(one, two);
  EXPECT_EQ(one.report.at("proxy").at("faces"), two.report.at("proxy").at("faces"));
  EXPECT_EQ(one.report.at("proxy").at("distance_bound"),
            two.report.at("proxy").at("distance_bound"));
}

TEST(Proxy, WithAndWithoutAProxyBothCertifiedAgainstTheInput) {
  const std::vector<std::pair<std::string, TriangleMesh>> shapes = {
      {"sphere", sphere({.radius = 1.0, .subdivisions = 4})},
      {"torus", torus({.segments = 96, .tube_segments = 40})}};
  const std::string forced = forced_proxy_config();
  for (const auto& [name, mesh] : shapes) {
    SCOPED_TRACE(name);
    const auto with = run_pipeline(mesh, "5%", name + "_proxy", 0, forced);
    const auto without = run_pipeline(mesh, "5%", name + "_full", 0, config_without_proxy());
    expect_certified(mesh, with);
    expect_certified(mesh, without);
    const auto& proxy = with.report.at("proxy");
    ASSERT_TRUE(proxy.at("used").get<bool>()) << proxy.at("reason");
    EXPECT_EQ(proxy.at("method"), "decimate");
    EXPECT_LT(proxy.at("faces").get<std::size_t>(), mesh.triangles.size() / 2);
    const double tau = with.report.at("tolerance").at("absolute").get<double>();
    const double e = proxy.at("distance_bound").get<double>();
    EXPECT_GT(e, 0.0);
    EXPECT_LE(e, 0.2 * tau);
    EXPECT_DOUBLE_EQ(proxy.at("refinement_tolerance").get<double>(), tau - e);
    const auto& result = with.report.at("result");
    EXPECT_LE(result.at("strips_bound").get<double>(), tau - e);
    EXPECT_DOUBLE_EQ(result.at("hausdorff_bound").get<double>(),
                     result.at("strips_bound").get<double>() + e);
    // error.ply keeps measuring the original input: one vertex per input vertex.
    const std::string ply = testing::read_text(with.dir / "error.ply");
    EXPECT_NE(ply.find("element vertex " + std::to_string(mesh.vertices.size()) + "\n"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace papercraft
