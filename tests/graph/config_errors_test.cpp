#include <gtest/gtest.h>

#include "core/errors.h"
#include "graph/config.h"
#include "support/test_nodes.h"

namespace papercraft {
namespace {

// Parses `yaml` expecting a ConfigException whose message starts with "cfg.yaml:L:C: " and
// contains every one of `words`.
void expect_error(const std::string& yaml, int line, int column,
                  const std::vector<std::string>& words) {
  static const Registry registry = testing::test_registry();
  try {
    parse_pipeline_config(yaml, "cfg.yaml", registry);
    FAIL() << "expected a ConfigException for:\n" << yaml;
  } catch (const ConfigException& e) {
    const std::string message = e.what();
    const std::string where =
        "cfg.yaml:" + std::to_string(line) + ":" + std::to_string(column) + ": ";
    EXPECT_EQ(message.rfind(where, 0), 0u) << message;
    for (const auto& w : words) EXPECT_NE(message.find(w), std::string::npos) << message;
  }
}

TEST(ConfigErrors, UnknownNodeTypeListsKnownOnes) {
  expect_error("nodes:\n  source: {impl: test.nope}\n", 2, 18,
               {"unknown node implementation 'test.nope'", "test.source", "test.sink"});
}

TEST(ConfigErrors, UnknownTopLevelKey) {
  expect_error("nodez: {}\n", 1, 1, {"unknown key 'nodez'", "nodes"});
}

TEST(ConfigErrors, PaperLimitsMustBeNumbersAtLeastZero) {
  const std::string nodes = "nodes:\n  source: {impl: test.source}\n";
  expect_error("min_width_mm: -5\n" + nodes, 1, 15, {"min_width_mm must be at least 0", "-5"});
  expect_error("min_area_mm2: lots\n" + nodes, 1, 15, {"min_area_mm2: expected a number"});
  expect_error("height_mm: 0\n" + nodes, 1, 12, {"height_mm must be greater than 0"});
  static const Registry registry = testing::test_registry();
  const PipelineConfig config = parse_pipeline_config(
      "min_width_mm: 0\nmin_area_mm2: 250\nscale: 2.5\n" + nodes, "cfg.yaml", registry);
  EXPECT_EQ(config.min_width_mm, 0.0);
  EXPECT_EQ(config.min_area_mm2, 250.0);
  EXPECT_EQ(config.scale, 2.5);
  EXPECT_FALSE(config.height_mm.has_value());
}

TEST(ConfigErrors, EffortWeightsMustBeNumbersAtLeastZero) {
  const std::string nodes = "nodes:\n  source: {impl: test.source}\n";
  expect_error("effort: {seam: -1}\n" + nodes, 1, 16, {"effort.seam must be at least 0", "-1"});
  expect_error("effort: {piece: .nan}\n" + nodes, 1, 17, {"effort.piece: expected a number"});
  expect_error("effort: {sawtooth: lots}\n" + nodes, 1, 20, {"effort.sawtooth: expected a number"});
  expect_error("effort: {pieces: 1}\n" + nodes, 1, 10, {"unknown key 'pieces'", "glue_per_metre"});
  expect_error("effort: 3\n" + nodes, 1, 9, {"effort: expected a map"});
  static const Registry registry = testing::test_registry();
  const PipelineConfig config = parse_pipeline_config(
      "effort:\n  seam: 2\n  narrow_piece: 0\n" + nodes, "cfg.yaml", registry);
  ASSERT_TRUE(config.effort.has_value());
  EXPECT_EQ(config.effort->seam, 2.0);
  EXPECT_EQ(config.effort->narrow_piece, 0.0);
  EXPECT_EQ(config.effort->piece, EffortWeights{}.piece);  // not given: the default
  EXPECT_FALSE(parse_pipeline_config(nodes, "cfg.yaml", registry).effort.has_value());
}

TEST(ConfigErrors, UnknownNodeKey) {
  expect_error("nodes:\n  source: {impl: test.source, too: [x]}\n", 2, 31,
               {"unknown key 'too'", "node 'source'"});
}

TEST(ConfigErrors, MissingKeys) {
  expect_error("tolerance: 2%\n", 1, 1, {"missing key 'nodes'"});
  expect_error("nodes:\n  source: {params: {count: 2}}\n", 2, 11,
               {"missing key 'impl'", "node 'source'"});
}

TEST(ConfigErrors, DuplicateKeys) {
  expect_error("nodes:\n  a: {impl: test.source}\n  a: {impl: test.source}\n", 3, 3,
               {"duplicate key 'a'"});
  expect_error("nodes:\n  a: {impl: test.source, impl: test.double}\n", 2, 26,
               {"duplicate key 'impl'"});
}

TEST(ConfigErrors, BadValues) {
  expect_error("nodes:\n  source: {impl: test.source, params: {count: many}}\n", 2, 47,
               {"parameter 'count'", "expected an integer", "many"});
  expect_error("nodes:\n  source: {impl: test.source, params: {cuont: 2}}\n", 2, 40,
               {"unknown parameter 'cuont'", "count", "fail_every"});
  expect_error("tolerance: lots\nnodes:\n  source: {impl: test.source}\n", 1, 12,
               {"expected a positive tolerance"});
  expect_error("nodes:\n  source: {impl: test.source, concurrency: -2}\n", 2, 44,
               {"concurrency >= 0"});
}

TEST(ConfigErrors, TypeMismatchOnEdgeNamesBothEnds) {
  expect_error("nodes:\n  source: {impl: test.source, to: [sink]}\n  sink: {impl: test.sink}\n", 2,
               36, {"type mismatch", "source", "emits Item", "sink (test.sink) takes Summary"});
}

TEST(ConfigErrors, EdgeToUnknownNode) {
  expect_error("nodes:\n  source: {impl: test.source, to: [nowhere]}\n", 2, 36,
               {"unknown node 'nowhere'"});
}

TEST(ConfigErrors, PortsOfMultiOutputNode) {
  expect_error(
      "nodes:\n  source: {impl: test.source, to: [loop]}\n  loop: {impl: test.loop, to: "
      "[loop]}\n",
      3, 31, {"has outputs done, again", "expected 'to: {done: [node, ...], ...}'"});
  expect_error(
      "nodes:\n  source: {impl: test.source, to: [loop]}\n  loop: {impl: test.loop, to: "
      "{dnoe: [loop]}}\n",
      3, 32, {"unknown key 'dnoe'", "done, again"});
}

TEST(ConfigErrors, CycleWithoutBackEdge) {
  expect_error(
      "nodes:\n  source: {impl: test.source, to: [loop]}\n"
      "  loop: {impl: test.loop, to: {done: [sink], again: [loop]}}\n"
      "  sink: {impl: test.item_sink}\n",
      3, 54, {"cycle loop -> loop", "without a marked back edge", "back:"});
}

TEST(ConfigErrors, NodeNobodyFeeds) {
  expect_error(
      "nodes:\n  source: {impl: test.source, to: [sink]}\n  sink: {impl: test.item_sink}\n"
      "  orphan: {impl: test.double, to: [sink]}\n",
      4, 3, {"node 'orphan' is fed by no other node"});
}

TEST(ConfigErrors, InvalidYamlHasPosition) {
  expect_error("nodes:\n  source: {impl: test.source\n", 3, 1, {"invalid YAML"});
}

TEST(Config, ValidConfigParses) {
  const Registry registry = testing::test_registry();
  PipelineConfig config = parse_pipeline_config(
      "tolerance: 1.5%\nthreads: 2\nnodes:\n  source: {impl: test.source, params: {count: 7}, "
      "to: [sink]}\n  sink: {impl: test.item_sink}\n",
      "ok.yaml", registry);
  ASSERT_TRUE(config.tolerance.has_value());
  EXPECT_TRUE(config.tolerance->relative);
  EXPECT_DOUBLE_EQ(config.tolerance->value, 0.015);
  EXPECT_EQ(config.threads, 2);
  EXPECT_EQ(config.nodes.size(), 2u);
  EXPECT_EQ(config.nodes[0].params.integer("count"), 7);
  EXPECT_EQ(config.nodes[0].params.integer("fail_every"), 0) << "defaults filled in";
  EXPECT_EQ(config.entry, 0);
}

}  // namespace
}  // namespace papercraft
