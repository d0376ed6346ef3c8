#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "graph/config.h"
#include "graph/pipeline.h"
#include "support/test_nodes.h"

namespace papercraft {
namespace {

using testing::test_registry;

long tally(int model, const std::string& key) {
  return testing::tally.get(model, key);
}

std::vector<ModelResult> run_config(const std::string& yaml, int models, int threads) {
  static const Registry registry = test_registry();
  testing::tally.clear();
  Pipeline pipeline(parse_pipeline_config(yaml, "inline.yaml", registry), registry);
  std::vector<std::filesystem::path> inputs;
  for (int i = 0; i < models; ++i) inputs.push_back("model" + std::to_string(i) + ".obj");
  PipelineOptions options;
  options.threads = threads;
  return pipeline.run(inputs, std::make_shared<RunSettings>(), options);
}

class Builder : public ::testing::TestWithParam<int> {};

TEST_P(Builder, LinearChain) {
  auto results = run_config(R"(
nodes:
  source: {impl: test.source, params: {count: 4}, to: [double]}
  double: {impl: test.double, to: [sink]}
  sink:   {impl: test.item_sink}
)",
                            3, GetParam());
  ASSERT_EQ(results.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(results[i].ok) << results[i].error;
    EXPECT_EQ(tally(i, "items"), 4);
    EXPECT_EQ(tally(i, "sum"), 2 * (1 + 2 + 3 + 4));
  }
}

TEST_P(Builder, LoopWithBackEdgeTerminates) {
  // Each item v < 6 splits into two items v+1 until 6: from 1, 2^5 = 32 items reach the sink.
  auto results = run_config(R"(
nodes:
  source: {impl: test.source, params: {count: 1}, to: [loop]}
  loop:   {impl: test.loop, params: {limit: 6}, to: {done: [collect]}, back: {again: [loop]}}
  collect: {impl: test.collect, to: [sink]}
  sink:   {impl: test.sink}
)",
                            5, GetParam());
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(results[i].ok) << results[i].error;
    EXPECT_EQ(tally(i, "count"), 32);
    EXPECT_EQ(tally(i, "sum"), 32 * 6);
    EXPECT_EQ(tally(i, "sink_calls"), 1);
  }
}

TEST_P(Builder, MultiOutputRouting) {
  auto results = run_config(R"(
nodes:
  source: {impl: test.source, params: {count: 10}, to: [split]}
  split:  {impl: test.even, to: {even: [evens], odd: [double]}}
  double: {impl: test.double, to: [evens]}
  evens:  {impl: test.item_sink}
)",
                            2, GetParam());
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(results[i].ok) << results[i].error;
    EXPECT_EQ(tally(i, "items"), 10);
    // evens 2+4+6+8+10 = 30, odds doubled 2*(1+3+5+7+9) = 50
    EXPECT_EQ(tally(i, "sum"), 80);
  }
}

TEST_P(Builder, CompletionFiresExactlyOncePerModelWith50InFlight) {
  testing::sink_calls = 0;
  testing::tally.clear();
  static const Registry registry = test_registry();
  Pipeline pipeline(parse_pipeline_config(R"(
nodes:
  source: {impl: test.source, params: {count: 3}, to: [loop]}
  loop:   {impl: test.loop, params: {limit: 8}, to: {done: [collect]}, back: {again: [loop]}}
  collect: {impl: test.collect, to: [sink]}
  sink:   {impl: test.sink}
)",
                                          "inline.yaml", registry),
                    registry);
  std::vector<std::filesystem::path> inputs(50, "same-name.off");
  PipelineOptions options;
  options.threads = GetParam();
  options.max_models_in_flight = 50;
  std::atomic<int> done{0};
  options.on_model_done = [&](const ModelRun&, const ModelResult&) { done.fetch_add(1); };
  auto results = pipeline.run(inputs, std::make_shared<RunSettings>(), options);
  EXPECT_EQ(done.load(), 50);
  EXPECT_EQ(testing::sink_calls.load(), 50);
  std::set<std::string> names;
  for (int i = 0; i < 50; ++i) {
    ASSERT_TRUE(results[i].ok) << results[i].error;
    names.insert(results[i].name);
    EXPECT_EQ(tally(i, "sink_calls"), 1);
    // items 1,2,3 each double until 8: 2^7 + 2^6 + 2^5 = 224 items of value 8
    EXPECT_EQ(tally(i, "count"), 224);
    EXPECT_EQ(tally(i, "sum"), 224 * 8);
  }
  EXPECT_EQ(names.size(), 50u) << "output names must be unique";
}

TEST_P(Builder, FailingModelDoesNotLoseOthers) {
  auto results = run_config(R"(
nodes:
  source: {impl: test.source, params: {count: 2, fail_every: 3}, to: [collect]}
  collect: {impl: test.collect, to: [sink]}
  sink:   {impl: test.sink}
)",
                            9, GetParam());
  int failed = 0;
  for (int i = 0; i < 9; ++i) {
    const ModelResult& r = results[i];
    if (r.name == "model1" || r.name == "model4" || r.name == "model7") {
      EXPECT_FALSE(r.ok);
      EXPECT_FALSE(r.internal_error) << "a bad model is not a bug";
      EXPECT_NE(r.error.find("bad model"), std::string::npos) << r.error;
      EXPECT_NE(r.error.find("source"), std::string::npos) << "error names the node";
      EXPECT_FALSE(testing::tally.has(i, "sink_calls"));
      ++failed;
    } else {
      EXPECT_TRUE(r.ok) << r.error;
      EXPECT_EQ(tally(i, "sum"), 3);
    }
  }
  EXPECT_EQ(failed, 3);
}

TEST_P(Builder, ThreeOutputPortsRouteByName) {
  auto results = run_config(R"(
nodes:
  source: {impl: test.source, params: {count: 9}, to: [split]}
  split:  {impl: test.mod3, to: {zero: [zeros], one: [double], two: [double, zeros]}}
  double: {impl: test.double, to: [zeros]}
  zeros:  {impl: test.item_sink}
)",
                            2, GetParam());
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(results[i].ok) << results[i].error;
    // zero: 3 + 6 + 9; one: 2 (1 + 4 + 7) doubled; two goes to both: 2 (2 + 5 + 8) + 2 + 5 + 8
    EXPECT_EQ(tally(i, "items"), 3 + 3 + 2 * 3);
    EXPECT_EQ(tally(i, "sum"), 18 + 24 + 30 + 15);
  }
}

TEST_P(Builder, EmittingOnAnUndeclaredPortIsAnInternalError) {
  auto results = run_config(R"(
nodes:
  source: {impl: test.source, params: {count: 2}, to: [rogue]}
  rogue:  {impl: test.rogue, to: [sink]}
  sink:   {impl: test.item_sink}
)",
                            2, GetParam());
  for (const ModelResult& r : results) {
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.internal_error) << r.error;
    EXPECT_NE(r.error.find("'undeclared'"), std::string::npos) << r.error;
  }
}

TEST_P(Builder, NodeStatisticsCountCalls) {
  static const Registry registry = test_registry();
  Pipeline pipeline(parse_pipeline_config(R"(
nodes:
  source: {impl: test.source, params: {count: 5}, to: [double]}
  double: {impl: test.double, concurrency: 1, to: [sink]}
  sink:   {impl: test.item_sink}
)",
                                          "inline.yaml", registry),
                    registry);
  std::vector<NodeTiming> timings;
  PipelineOptions options;
  options.threads = GetParam();
  options.on_model_done = [&](const ModelRun& run, const ModelResult&) {
    timings = pipeline.timings(run);
  };
  pipeline.run({"a.obj"}, std::make_shared<RunSettings>(), options);
  ASSERT_EQ(timings.size(), 3u);
  EXPECT_EQ(timings[0].calls, 1);
  EXPECT_EQ(timings[1].calls, 5);
  EXPECT_EQ(timings[2].calls, 5);
  EXPECT_EQ(timings[1].impl, "test.double");
}

INSTANTIATE_TEST_SUITE_P(Threads, Builder, ::testing::Values(1, 2));

}  // namespace
}  // namespace papercraft
