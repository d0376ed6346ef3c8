#include "runner/progress_display.h"

#include <gtest/gtest.h>

namespace papercraft {
namespace {

TEST(ProgressDisplay, Durations) {
  EXPECT_EQ(format_duration(0.4), "0s");
  EXPECT_EQ(format_duration(59.4), "59s");
  EXPECT_EQ(format_duration(72), "1m12s");
  EXPECT_EQ(format_duration(7380), "2h03m");
}

TEST(ProgressDisplay, TextOfABatch) {
  PipelineProgress p;
  p.total = 40;
  p.done = 10;
  p.failed = 1;
  p.running = {{"a", "hausdorff", 3}, {"b", "load", 1}};
  // 10 done in 60 s: 30 more take about 180 s.
  EXPECT_EQ(progress_text(p, 2, 60.0),
            "10/40 done, 1 failed, 2 skipped, 1m00s elapsed, about 3m00s left; 2 running");
  p.done = 0;
  p.failed = 0;
  EXPECT_EQ(progress_text(p, 0, 5.0), "0/40 done, 5s elapsed; 2 running");
}

TEST(ProgressDisplay, TextOfOneModelNamesItsStage) {
  PipelineProgress p;
  p.total = 1;
  p.running = {{"cow", "cut", 12}};
  EXPECT_EQ(progress_text(p, 0, 3.0), "0/1 done, 3s elapsed; cow: cut, 12 parts in flight");
  p.running = {{"caf\xE9", "load", 1}};
  EXPECT_EQ(progress_text(p, 0, 3.0), "0/1 done, 3s elapsed; caf\\xE9: load, 1 part in flight");
}

}  // namespace
}  // namespace papercraft
