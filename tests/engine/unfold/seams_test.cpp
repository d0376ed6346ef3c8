#include "core/seams.h"

#include <gtest/gtest.h>

#include <set>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "engine/unfold/sequential.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using unfold_testing::circle_point;
using unfold_testing::ladder_strip;
using unfold_testing::ring_strip;

std::vector<Vec3> arc(int n, double z) {
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.push_back(circle_point(1.0, i, 3 * n, z));
  return points;
}

void append(std::vector<FlatStrip>& all, const RuledStrip& strip, int source) {
  auto flat = unfold_strip(strip, source, static_cast<int>(all.size()));
  all.insert(all.end(), flat.begin(), flat.end());
}

bool at_height(const FlatStrip& s, const BoundaryEdge& e, double z) {
  return s.vertices3d[e.v0].z() == z && s.vertices3d[e.v1].z() == z;
}

void expect_seam_or_open(const std::vector<FlatStrip>& strips) {
  for (const FlatStrip& s : strips)
    for (const BoundaryEdge& e : s.boundary) {
      EXPECT_NE(e.kind, EdgeKind::Cut);
      EXPECT_EQ(e.kind == EdgeKind::Seam, !e.label.empty());
      EXPECT_EQ(e.kind == EdgeKind::Seam, e.neighbour_strip >= 0);
    }
}

// Two open strips stacked on a shared arc: that arc is one seam, labelled alike on both sides.
TEST(LabelSeams, StripsSharingAPolylineGetOneLabel) {
  const int n = 10;
  std::vector<FlatStrip> strips;
  append(strips, ladder_strip(arc(n, 0.0), arc(n, 1.0), false), 0);
  append(strips, ladder_strip(arc(n, 1.0), arc(n, 2.5), false), 1);
  ASSERT_EQ(strips.size(), 2u);
  label_seams(strips);
  expect_seam_or_open(strips);
  std::set<std::string> labels[2];
  for (int k = 0; k < 2; ++k) {
    int seams = 0;
    for (const BoundaryEdge& e : strips[k].boundary) {
      bool shared = at_height(strips[k], e, 1.0);
      EXPECT_EQ(e.kind, shared ? EdgeKind::Seam : EdgeKind::Open);
      if (!shared) continue;
      ++seams;
      EXPECT_EQ(e.neighbour_strip, strips[1 - k].id);
      labels[k].insert(e.label);
    }
    EXPECT_EQ(seams, n - 1);
  }
  EXPECT_EQ(labels[0].size(), 1u);
  EXPECT_EQ(labels[0], labels[1]);
  EXPECT_EQ(*labels[0].begin(), "A1");
}

// The ruling a closed strip was opened along is a seam with the strip itself.
TEST(LabelSeams, OpenedRulingIsSeamWithItself) {
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(1.0, 0.0, 1.0, 1.0, 12), 0);
  strips[0].id = 5;
  label_seams(strips);
  expect_seam_or_open(strips);
  std::vector<const BoundaryEdge*> seams;
  for (const BoundaryEdge& e : strips[0].boundary) {
    bool circle = at_height(strips[0], e, 0.0) || at_height(strips[0], e, 1.0);
    EXPECT_EQ(e.kind, circle ? EdgeKind::Open : EdgeKind::Seam);
    if (!circle) seams.push_back(&e);
  }
  ASSERT_EQ(seams.size(), 2u);
  EXPECT_EQ(seams[0]->neighbour_strip, 5);
  EXPECT_EQ(seams[1]->neighbour_strip, 5);
  EXPECT_EQ(seams[0]->label, seams[1]->label);
}

// A fan split by unfolding: every cut between its pieces is a seam, nothing is left Cut.
TEST(LabelSeams, SplitFanPiecesAreSeamedTogether) {
  const int n = 40;
  std::vector<FlatStrip> strips;
  append(strips, unfold_testing::saddle_fan(n), 0);
  ASSERT_GE(strips.size(), 2u);
  label_seams(strips);
  expect_seam_or_open(strips);
  int open = 0;
  for (const FlatStrip& s : strips)
    for (const BoundaryEdge& e : s.boundary) {
      // Rulings (through the apex) are seams, A's edges the open rim.
      bool ruling = s.vertices3d[e.v0] == Vec3::Zero() || s.vertices3d[e.v1] == Vec3::Zero();
      EXPECT_EQ(e.kind, ruling ? EdgeKind::Seam : EdgeKind::Open);
      open += e.kind == EdgeKind::Open;
      if (!ruling) continue;
      EXPECT_GE(e.neighbour_strip, strips.front().id);
      EXPECT_LE(e.neighbour_strip, strips.back().id);
    }
  EXPECT_EQ(open, n);
}

// Hand-made flat strips: quads [x0, x1] x [y0, y1] in the z = 0 plane (2D = 3D), bottom
// edge subdivided at the given x.
FlatStrip quad(int id, double x0, double x1, double y0, double y1, std::vector<double> bottom) {
  FlatStrip s;
  s.id = id;
  bottom.insert(bottom.begin(), x0);
  bottom.push_back(x1);
  const int n = static_cast<int>(bottom.size());
  for (double x : bottom) s.vertices3d.push_back(Vec3(x, y0, 0.0));
  s.vertices3d.push_back(Vec3(x1, y1, 0.0));
  s.vertices3d.push_back(Vec3(x0, y1, 0.0));
  for (const Vec3& p : s.vertices3d) s.vertices2d.push_back(p.head<2>());
  for (int i = 0; i + 1 < n; ++i) s.triangles.push_back({i, i + 1, n + 1});
  s.triangles.push_back({n - 1, n, n + 1});
  s.boundary = flat_boundary(s.triangles);
  return s;
}

// A neighbour whose side has extra vertices (a T-junction: it was cut after this strip was
// made): the long edge is split at them, in 3D, in 2D and in its triangle, and each piece is
// glued to exactly one edge of the same length.
TEST(LabelSeams, TJunctionsAreSplitSoEveryEdgeHasOnePartner) {
  std::vector<FlatStrip> strips = {quad(0, 0.0, 1.0, -1.0, 0.0, {}),
                                   quad(1, 0.0, 1.0, 0.0, 1.0, {0.25, 0.7})};
  auto edge_on_y0 = [](const FlatStrip& s, const BoundaryEdge& e) {
    return s.vertices3d[e.v0].y() == 0.0 && s.vertices3d[e.v1].y() == 0.0;
  };
  auto unsplit = strips;
  label_seams(unsplit);
  for (const FlatStrip& s : unsplit)
    for (const BoundaryEdge& e : s.boundary) EXPECT_EQ(e.kind, EdgeKind::Open);

  const double area_before = strips[0].triangles.size();
  EXPECT_EQ(split_t_junctions(strips), 2);
  EXPECT_EQ(split_t_junctions(strips), 0) << "a second pass finds nothing";
  EXPECT_EQ(strips[0].triangles.size(), area_before + 2);
  EXPECT_EQ(strips[0].vertices3d.size(), 6u);
  EXPECT_EQ(first_clockwise_triangle(strips[0].vertices2d, strips[0].triangles, 1e-12), -1);
  label_seams(strips);
  expect_seam_or_open(strips);
  std::set<std::string> labels;
  int seams = 0;
  for (int k = 0; k < 2; ++k)
    for (const BoundaryEdge& e : strips[k].boundary) {
      bool shared = edge_on_y0(strips[k], e);
      EXPECT_EQ(e.kind, shared ? EdgeKind::Seam : EdgeKind::Open);
      if (!shared) continue;
      ++seams;
      EXPECT_EQ(e.neighbour_strip, 1 - k);
      const BoundaryEdge& partner = strips[1 - k].boundary.at(e.partner_edge);
      EXPECT_EQ(strips[1 - k].vertices3d[partner.v0], strips[k].vertices3d[e.v1]);
      EXPECT_EQ(strips[1 - k].vertices3d[partner.v1], strips[k].vertices3d[e.v0]);
      const double here = (strips[k].vertices2d[e.v1] - strips[k].vertices2d[e.v0]).norm();
      const double there =
          (strips[1 - k].vertices2d[partner.v1] - strips[1 - k].vertices2d[partner.v0]).norm();
      EXPECT_NEAR(here, there, 1e-12);
      labels.insert(e.label);
    }
  EXPECT_EQ(seams, 6);  // three pieces of the long edge against three short ones
  EXPECT_EQ(labels.size(), 1u);
  const std::vector<SeamChain> chains = labelled_chains(strips);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_EQ(chains[0].sides[0].edges.size(), 3u);
  EXPECT_EQ(chains[0].sides[1].edges.size(), 3u);
  EXPECT_NE(chains[0].sides[0].strip, chains[0].sides[1].strip);
}

// Three strips on one edge: the two traversing it oppositely pair up, the third stays open
// (an edge has one partner); the same on every run.
TEST(LabelSeams, EdgeWithSeveralPartnersIsPairedDeterministically) {
  std::vector<FlatStrip> strips = {quad(0, 0.0, 1.0, -1.0, 0.0, {}),
                                   quad(1, 0.0, 1.0, 0.0, 1.0, {}),
                                   quad(2, 0.0, 1.0, 0.0, 1.0, {})};
  for (Vec3& p : strips[2].vertices3d)
    if (p.y() != 0.0) p.z() = 1.0;  // a fin standing on the same edge
  label_seams(strips);
  auto again = strips;
  label_seams(again);
  std::vector<int> neighbours;
  std::set<std::string> labels;
  for (std::size_t k = 0; k < strips.size(); ++k)
    for (std::size_t e = 0; e < strips[k].boundary.size(); ++e) {
      const BoundaryEdge& edge = strips[k].boundary[e];
      EXPECT_EQ(edge.kind, again[k].boundary[e].kind);
      EXPECT_EQ(edge.label, again[k].boundary[e].label);
      EXPECT_EQ(edge.neighbour_strip, again[k].boundary[e].neighbour_strip);
      if (edge.kind != EdgeKind::Seam) continue;
      neighbours.push_back(edge.neighbour_strip);
      labels.insert(edge.label);
    }
  // Strip 0 runs (1,0)->(0,0), strips 1 and 2 run (0,0)->(1,0): 0 pairs with 1.
  EXPECT_EQ(neighbours, (std::vector<int>{1, 0}));
  EXPECT_EQ(labels.size(), 1u);
}

// One label per chain shared by two strips: a strip glued along one boundary to two others
// gets two labels, where the old rule joined them through the shared vertex.
TEST(LabelSeams, ALabelNamesOneChainBetweenTwoStrips) {
  std::vector<FlatStrip> strips = {quad(0, 0.0, 2.0, -1.0, 0.0, {1.0}),
                                   quad(1, 0.0, 1.0, 0.0, 1.0, {}),
                                   quad(2, 1.0, 2.0, 0.0, 1.0, {})};
  // Strip 0's top edge is a single edge (0,0)-(2,0) whose partners are split by vertex (1,0).
  split_t_junctions(strips);
  label_seams(strips);
  std::set<std::string> to1, to2;
  for (const BoundaryEdge& e : strips[0].boundary) {
    if (e.neighbour_strip == 1) to1.insert(e.label);
    if (e.neighbour_strip == 2) to2.insert(e.label);
  }
  ASSERT_EQ(to1.size(), 1u);
  ASSERT_EQ(to2.size(), 1u);
  EXPECT_NE(*to1.begin(), *to2.begin());
  for (const SeamChain& chain : labelled_chains(strips)) {
    EXPECT_EQ(chain.sides[0].edges.size(), chain.sides[1].edges.size()) << chain.label;
    EXPECT_GE(chain.sides[1].strip, 0) << chain.label;
  }
}

// Two strips of opposite orientation (the second is the first mirrored across their shared
// side, its triangles listed alike): their boundaries run the same way along the seam, which is
// still one chain with one label, the same three edges on both sides.
TEST(LabelSeams, PartnersRunningTheSameWayAreOneChain) {
  std::vector<FlatStrip> strips = {quad(0, 0.0, 3.0, 0.0, 1.0, {1.0, 2.0}),
                                   quad(1, 0.0, 3.0, 0.0, -1.0, {1.0, 2.0})};
  label_seams(strips);
  std::set<std::string> labels[2];
  for (int k = 0; k < 2; ++k)
    for (const BoundaryEdge& e : strips[k].boundary)
      if (e.kind == EdgeKind::Seam) {
        EXPECT_EQ(e.neighbour_strip, 1 - k);
        labels[k].insert(e.label);
      }
  EXPECT_EQ(labels[0], (std::set<std::string>{"A1"}));
  EXPECT_EQ(labels[1], labels[0]);
  const std::vector<SeamChain> chains = labelled_chains(strips);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_EQ(chains[0].sides[0].edges.size(), 3u);
  EXPECT_EQ(chains[0].sides[1].edges.size(), 3u);
}

// Two separate shared boundaries get two labels, numbered in strip order.
TEST(LabelSeams, SeparateBoundariesGetSeparateLabels) {
  const int n = 8;
  std::vector<FlatStrip> strips;
  append(strips, ladder_strip(arc(n, 0.0), arc(n, 1.0), false), 0);
  append(strips, ladder_strip(arc(n, 1.0), arc(n, 2.0), false), 1);
  append(strips, ladder_strip(arc(n, 2.0), arc(n, 3.0), false), 2);
  label_seams(strips);
  std::set<std::string> lower, upper;
  for (const FlatStrip& s : strips)
    for (const BoundaryEdge& e : s.boundary) {
      if (at_height(s, e, 1.0)) lower.insert(e.label);
      if (at_height(s, e, 2.0)) upper.insert(e.label);
    }
  EXPECT_EQ(lower, (std::set<std::string>{"A1"}));
  EXPECT_EQ(upper, (std::set<std::string>{"A2"}));
}

TEST(LabelSeams, BadInputThrows) {
  std::vector<FlatStrip> strips = {quad(0, 0.0, 1.0, 0.0, 1.0, {})};
  strips[0].boundary[1].v1 = 42;
  EXPECT_THROW(label_seams(strips), InvalidInputException);
}

}  // namespace
}  // namespace papercraft
