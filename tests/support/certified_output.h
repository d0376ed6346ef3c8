#pragma once
// The certificate of an end-to-end run checked against an independent brute force
// (brute_force_hausdorff.h): report.json's bound is a true bound on the input.

#include <gtest/gtest.h>

#include "support/brute_force_hausdorff.h"
#include "support/pipeline_run.h"

namespace papercraft::testing {

/// Brute force never finds a point of the input farther from the strips (or the other way)
/// than report.json's bound, the bound is <= tau, and approximation.obj holds every 3D strip.
inline void expect_certified(const TriangleMesh& input, const PipelineOutput& out) {
  ASSERT_TRUE(out.result.ok) << out.result.error;
  const auto& result = out.report.at("result");
  EXPECT_TRUE(result.at("certified").get<bool>());
  const double bound = result.at("hausdorff_bound").get<double>();
  const double tau = out.report.at("tolerance").at("absolute").get<double>();
  EXPECT_LE(bound, tau);
  const TriangleMesh approximation = concatenate(out.strips);
  ASSERT_FALSE(approximation.triangles.empty());
  const auto brute = brute_force_hausdorff(input, approximation, 2);
  EXPECT_LE(brute.distance, bound * (1 + 1e-9) + 1e-12)
      << "brute force found a point at distance " << brute.distance << " (side " << brute.side
      << ") above the certified bound " << bound;
  EXPECT_EQ(static_cast<std::size_t>(result.at("strips_3d").get<long>()), out.strips.size());
}

}  // namespace papercraft::testing
