#include "graph/model_run.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/errors.h"

namespace papercraft {
namespace {

std::unique_ptr<ModelRun> loaded_model(double largest_side) {
  auto settings = std::make_shared<RunSettings>();
  settings->tolerance = parse_tolerance("2%");
  auto model = std::make_unique<ModelRun>(0, "in.obj", "in", settings, 0);
  MeshSummary input;
  input.largest_side = largest_side;
  model->set_input(input);
  return model;
}

TEST(ModelRun, WithoutAProxyTheStripsAreRefinedAtTheTolerance) {
  const auto run = loaded_model(10.0);
  const ModelRun& model = *run;
  EXPECT_DOUBLE_EQ(model.tolerance(), 0.2);
  EXPECT_EQ(model.proxy_distance(), 0.0);
  EXPECT_EQ(model.refinement_tolerance(), model.tolerance());
  const ModelRecord record = model.record();
  EXPECT_FALSE(record.proxy.used);
  EXPECT_EQ(record.proxy.method, "none");
  EXPECT_EQ(record.proxy.distance_bound, 0.0);
}

TEST(ModelRun, AProxyLeavesTheRestOfTheTolerance) {
  const auto run = loaded_model(10.0);
  ModelRun& model = *run;
  model.set_proxy_distance(0.03);
  EXPECT_DOUBLE_EQ(model.proxy_distance(), 0.03);
  EXPECT_DOUBLE_EQ(model.refinement_tolerance(), 0.17);
  EXPECT_DOUBLE_EQ(model.tolerance(), 0.2) << "the user's tolerance is what the bound is held to";
  EXPECT_THROW(model.set_proxy_distance(0.2), InternalError);
  EXPECT_THROW(model.set_proxy_distance(-0.01), InternalError);
}

}  // namespace
}  // namespace papercraft
