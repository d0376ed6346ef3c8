// Pipeline::run stopped from outside (stop_starting, abandon), its per-model times and
// callbacks, and names given by the caller.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "graph/config.h"
#include "graph/pipeline.h"
#include "support/test_nodes.h"

namespace papercraft {
namespace {

using testing::test_registry;

const Registry& registry() {
  static const Registry r = test_registry();
  return r;
}

Pipeline sleepy_pipeline(int items, int milliseconds) {
  // Appended, not `"..." + std::to_string(...)`, which trips GCC 12's -Wrestrict.
  std::string yaml = "nodes:\n  source: {impl: test.source, params: {count: ";
  yaml.append(std::to_string(items));
  yaml.append(
      "}, to: [sleep]}\n  sleep: {impl: test.sleep, concurrency: 1, params: {milliseconds: ");
  yaml.append(std::to_string(milliseconds));
  yaml.append("}, to: [sink]}\n  sink: {impl: test.item_sink}\n");
  return Pipeline(parse_pipeline_config(yaml, "inline.yaml", registry()), registry());
}

std::vector<std::filesystem::path> inputs(int n) {
  std::vector<std::filesystem::path> out;
  for (int i = 0; i < n; ++i) {
    std::string name = "m";
    name.append(std::to_string(i));
    name.append(".obj");
    out.emplace_back(name);
  }
  return out;
}

TEST(PipelineStop, StopStartingLeavesTheRestUnstarted) {
  Pipeline pipeline = sleepy_pipeline(2, 5);
  std::stop_source stop;
  PipelineOptions options;
  options.threads = 1;
  options.max_models_in_flight = 1;
  options.stop_starting = stop.get_token();
  std::atomic<int> started{0}, done{0};
  options.on_model_started = [&](const ModelRun&) { started.fetch_add(1); };
  options.on_model_done = [&](const ModelRun&, const ModelResult&) {
    if (done.fetch_add(1) == 1) stop.request_stop();
  };
  const auto results = pipeline.run(inputs(10), std::make_shared<RunSettings>(), options);
  ASSERT_EQ(results.size(), 10u);
  // One model at a time: the stop after the second leaves the eight others unstarted.
  EXPECT_EQ(started.load(), 2);
  EXPECT_EQ(done.load(), 2);
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(results[i].started, i < 2) << i;
    EXPECT_EQ(results[i].ok, i < 2) << i;
    EXPECT_FALSE(results[i].abandoned);
    EXPECT_EQ(results[i].name, "m" + std::to_string(i)) << "named also when not started";
  }
}

TEST(PipelineStop, AbandonDropsTheRestOfARunningModel) {
  // 40 items of 25 ms, one at a time: 1 s if nothing stops it.
  Pipeline pipeline = sleepy_pipeline(40, 25);
  std::stop_source abandon;
  PipelineOptions options;
  options.threads = 2;
  options.abandon = abandon.get_token();
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    abandon.request_stop();
  });
  testing::tally.clear();
  const auto start = std::chrono::steady_clock::now();
  const auto results = pipeline.run(inputs(1), std::make_shared<RunSettings>(), options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stopper.join();
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(results[0].started);
  EXPECT_FALSE(results[0].ok);
  EXPECT_TRUE(results[0].abandoned);
  EXPECT_LT(testing::tally.get(0, "items"), 40);
  EXPECT_LT(seconds, 0.8) << "the queued items were not dropped";
}

TEST(PipelineStop, TimesAndNames) {
  Pipeline pipeline = sleepy_pipeline(4, 20);
  PipelineOptions options;
  options.threads = 2;
  options.max_models_in_flight = 1;
  options.names = {"first", "second"};
  std::vector<std::string> seen;
  std::mutex mutex;
  options.on_model_done = [&](const ModelRun& model, const ModelResult&) {
    std::lock_guard lock(mutex);
    seen.push_back(model.name);
  };
  const auto results = pipeline.run(inputs(2), std::make_shared<RunSettings>(), options);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].name, "first");
  EXPECT_EQ(results[1].name, "second");
  EXPECT_EQ(seen, (std::vector<std::string>{"first", "second"}));
  for (const auto& r : results) {
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_GE(r.work_seconds, 4 * 0.020) << "four sleeps of 20 ms";
    EXPECT_GE(r.wall_seconds, 4 * 0.020) << "one sleep at a time";
  }
  // The first model waited for no other (no bound in seconds: a loaded machine delays it).
  EXPECT_LT(results[0].queue_seconds, results[1].queue_seconds);
  // One model in flight: the second waited for the first.
  EXPECT_GE(results[1].queue_seconds, results[0].wall_seconds * 0.9);

  options.names = {"only one"};
  EXPECT_THROW(pipeline.run(inputs(2), std::make_shared<RunSettings>(), options),
               std::invalid_argument);
}

TEST(PipelineStop, ProgressNamesTheStage) {
  Pipeline pipeline = sleepy_pipeline(10, 30);
  PipelineOptions options;
  options.threads = 1;
  options.progress_interval = std::chrono::milliseconds(20);
  std::mutex mutex;
  std::vector<PipelineProgress> seen;
  options.on_progress = [&](const PipelineProgress& p) {
    std::lock_guard lock(mutex);
    seen.push_back(p);
  };
  pipeline.run(inputs(1), std::make_shared<RunSettings>(), options);
  bool saw_sleep = false;
  for (const auto& p : seen) {
    EXPECT_EQ(p.total, 1u);
    for (const auto& r : p.running) {
      EXPECT_EQ(r.name, "m0");
      saw_sleep = saw_sleep || (r.stage == "sleep" && r.in_flight > 0);
    }
  }
  EXPECT_TRUE(saw_sleep) << seen.size() << " progress calls";
}

}  // namespace
}  // namespace papercraft
