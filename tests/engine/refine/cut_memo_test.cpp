// CutMemo: the cuts count_strips made are found again, exactly, by a refinement of the same
// part step by step (as the graph refines the part segment.feature chose), and nothing else
// takes them.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/generate.h"
#include "core/mesh.h"
#include "engine/refine/refine.h"

namespace papercraft {
namespace {

void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (auto v : a.vertices()) EXPECT_EQ(a.point(v), b.point(b.vertex_handle(v.idx())));
  for (auto f : a.faces()) {
    auto fa = a.cfv_iter(f);
    auto fb = b.cfv_iter(b.face_handle(f.idx()));
    for (int k = 0; k < 3; ++k, ++fa, ++fb) EXPECT_EQ(fa->idx(), fb->idx());
  }
}

TEST(CutMemo, ARefinementOfTheCountedPartTakesEveryCut) {
  const Mesh sphere_mesh = to_mesh(sphere({1.0, 3}));
  const RefineOptions options = at_tolerance({}, 0.02);
  CutMemo memo;
  const int strips = count_strips(sphere_mesh, options, 1000, {}, &memo);
  ASSERT_GT(strips, 1);
  ASSERT_GT(memo.size(), 0u);
  // Depth first as the graph goes: every rejected piece's cut is in the memo and is the cut
  // cut_rejected_piece makes.
  std::vector<Mesh> pending = {sphere_mesh};
  int cuts = 0, accepted = 0;
  while (!pending.empty() && cuts < 1000) {
    const Mesh piece = std::move(pending.back());
    pending.pop_back();
    const StripBoundaries boundaries = select_strip_boundaries(piece, options);
    const RuledStrip strip = build_strip(piece, boundaries, options);
    const StripVerdict verdict = decide_strip(piece, boundaries, strip, options);
    if (verdict.accept) {
      ++accepted;
      continue;
    }
    ++cuts;
    const std::vector<Mesh> made = cut_rejected_piece(piece, boundaries, verdict, 0, options, "");
    auto kept = memo.take(piece, boundaries, verdict);
    ASSERT_TRUE(kept.has_value()) << "cut " << cuts;
    ASSERT_EQ(kept->size(), made.size());
    for (std::size_t i = 0; i < made.size(); ++i) expect_same_mesh((*kept)[i], made[i]);
    EXPECT_FALSE(memo.take(piece, boundaries, verdict).has_value());  // taken once
    for (std::size_t i = made.size(); i-- > 0;) pending.push_back(made[i]);
  }
  EXPECT_EQ(accepted, strips);
  EXPECT_EQ(memo.size(), 0u);
}

TEST(CutMemo, AnotherVerdictOrBoundaryFindsNothing) {
  const Mesh sphere_mesh = to_mesh(sphere({1.0, 3}));
  const RefineOptions options = at_tolerance({}, 0.02);
  CutMemo memo;
  count_strips(sphere_mesh, options, 1000, {}, &memo);
  const StripBoundaries boundaries = select_strip_boundaries(sphere_mesh, options);
  const RuledStrip strip = build_strip(sphere_mesh, boundaries, options);
  const StripVerdict verdict = decide_strip(sphere_mesh, boundaries, strip, options);
  ASSERT_FALSE(verdict.accept);
  StripVerdict moved = verdict;
  moved.witness.x() += 1e-9;
  EXPECT_FALSE(memo.take(sphere_mesh, boundaries, moved).has_value());
  StripBoundaries swapped = boundaries;
  std::swap(swapped.first, swapped.second);
  EXPECT_FALSE(memo.take(sphere_mesh, swapped, verdict).has_value());
  Mesh nudged = sphere_mesh;  // the same faces with one point moved: another part
  nudged.point(nudged.vertex_handle(0))[2] += 1e-12;
  EXPECT_FALSE(memo.take(nudged, boundaries, verdict).has_value());
  EXPECT_TRUE(memo.take(sphere_mesh, boundaries, verdict).has_value());
}

TEST(CutMemo, KeepsNoMoreThanItsFaces) {
  const Mesh sphere_mesh = to_mesh(sphere({1.0, 3}));
  CutMemo memo(0);
  count_strips(sphere_mesh, at_tolerance({}, 0.02), 1000, {}, &memo);
  EXPECT_EQ(memo.size(), 0u);
}

}  // namespace
}  // namespace papercraft
