// End to end: pieces a person can cut and glue. Every seam edge has one partner of the same
// length and one label per chain on both sides; no piece is a sliver or a crumb where the
// shape allows better; the approximation stays certified (brute force).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/generate.h"
#include "core/pattern.h"
#include "core/piece_width.h"
#include "nodes/layout/pages.h"
#include "nodes/load/openmesh.h"
#include "support/brute_force_hausdorff.h"
#include "support/command.h"
#include "support/flat_strips_json.h"
#include "support/pattern_checks.h"
#include "support/pipeline_run.h"
#include "support/temp_dir.h"

namespace papercraft {
namespace {

using testing::read_flat_strips;
using testing::run_pipeline;

void expect_certified(const TriangleMesh& input, const testing::PipelineOutput& out) {
  ASSERT_TRUE(out.result.ok) << out.result.error;
  EXPECT_TRUE(out.report.at("result").at("certified").get<bool>());
  const double bound = out.report.at("result").at("hausdorff_bound").get<double>();
  EXPECT_LE(bound, out.report.at("tolerance").at("absolute").get<double>());
  const auto brute = testing::brute_force_hausdorff(input, testing::concatenate(out.strips), 2);
  EXPECT_LE(brute.distance, bound * (1 + 1e-9) + 1e-12);
}

// The seams of strips.json: edge by edge, and its "seams" list, side by side.
void expect_exact_seams(const testing::PipelineOutput& out) {
  ASSERT_TRUE(out.result.ok) << out.result.error;
  const nlohmann::json& strips = out.flat.at("strips");
  const testing::SeamFindings seams = testing::check_seams(strips);
  EXPECT_TRUE(seams.exact()) << seams.problems.size() << " problems, first: "
                             << (seams.problems.empty() ? "" : seams.problems.front());
  std::map<int, const nlohmann::json*> by_id;
  for (const auto& s : strips) by_id[s.at("id").get<int>()] = &s;
  std::set<std::string> listed;
  for (const auto& seam : out.flat.at("seams")) {
    const std::string label = seam.at("label").get<std::string>();
    EXPECT_TRUE(listed.insert(label).second) << "seam " << label << " listed twice";
    const auto& sides = seam.at("sides");
    ASSERT_EQ(sides.size(), 2u);
    std::size_t counts[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const auto& boundary = by_id.at(sides[k].at("strip").get<int>())->at("boundary");
      int previous_end = -1;
      for (const auto& e : sides[k].at("edges")) {
        const auto& edge = boundary.at(e.get<int>());
        EXPECT_EQ(edge.at("label").get<std::string>(), label);
        if (previous_end >= 0) {
          EXPECT_EQ(edge.at("v0").get<int>(), previous_end) << label;
        }
        previous_end = edge.at("v1").get<int>();
        // Its partner lies on the other side.
        const int partner = edge.at("partner_edge").get<int>();
        bool found = false;
        for (const auto& f : sides[1 - k].at("edges")) found = found || f.get<int>() == partner;
        EXPECT_TRUE(found) << "seam " << label << " edge " << e << ": partner off the other side";
        ++counts[k];
      }
    }
    EXPECT_EQ(counts[0], counts[1]) << label;
    EXPECT_GT(counts[0], 0u) << label;
  }
  // Every labelled edge belongs to a listed seam.
  for (const auto& s : strips)
    for (const auto& edge : s.at("boundary"))
      if (edge.at("kind") == "seam") {
        EXPECT_TRUE(listed.count(edge.at("label").get<std::string>()));
      }
}

double flat_area_mm2(const nlohmann::json& strip, double scale) {
  double area = 0.0;
  for (const auto& t : strip.at("triangles")) {
    const auto& a = strip.at("vertices2d").at(t.at(0).get<int>());
    const auto& b = strip.at("vertices2d").at(t.at(1).get<int>());
    const auto& c = strip.at("vertices2d").at(t.at(2).get<int>());
    area += 0.5 * std::abs((b[0].get<double>() - a[0].get<double>()) *
                               (c[1].get<double>() - a[1].get<double>()) -
                           (b[1].get<double>() - a[1].get<double>()) *
                               (c[0].get<double>() - a[0].get<double>()));
  }
  return area * scale * scale;
}

class ExactSeams : public ::testing::TestWithParam<std::string> {};

TEST_P(ExactSeams, EverySeamEdgeHasOnePartnerOfTheSameLength) {
  const TriangleMesh mesh = generate_shape(GetParam(), {});
  for (const char* tolerance : {"2%", "5%"}) {
    SCOPED_TRACE(GetParam() + " at " + tolerance);
    const auto out = run_pipeline(mesh, tolerance, GetParam());
    expect_exact_seams(out);
    const auto notes = out.report.at("notes").dump();
    EXPECT_EQ(notes.find("do not match"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("no partner edge"), std::string::npos) << notes;
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, ExactSeams,
                         ::testing::Values("open_cylinder", "elliptic_cylinder", "cone_frustum",
                                           "sphere", "torus", "figure_eight", "pawn",
                                           "cylinder_two_holes", "box", "capped_cylinder",
                                           "dumbbell"));

// The figure eight at 2% used to get a piece narrower than 3 mm over more than a quarter of
// it (a band 1.6 mm wide along a seam). Judged as the maker would: the share of each printed
// piece narrower than 3 mm stays under 25% (the 5 mm bound is what the cuts aim for; a strip
// may differ from its part by the tolerance, 4 mm here, so the printed bound is looser).
// The flat strips of `out` narrower than 3 mm on paper over more than a quarter of their area.
std::vector<int> narrow_pieces(const testing::PipelineOutput& out) {
  const double scale = out.report.at("result").at("mm_per_unit").get<double>();
  std::vector<int> narrow;
  for (const auto& strip : out.flat.at("strips")) {
    std::vector<Vec2> points;
    for (const auto& p : strip.at("vertices2d"))
      points.emplace_back(p[0].get<double>() * scale, p[1].get<double>() * scale);
    std::vector<Triangle> triangles;
    for (const auto& t : strip.at("triangles"))
      triangles.push_back({t[0].get<int>(), t[1].get<int>(), t[2].get<int>()});
    if (narrow_area_fraction(points, triangles, 3.0) > 0.25)
      narrow.push_back(strip.at("id").get<int>());
  }
  return narrow;
}

TEST(Pieces, NoSliverOnTheFigureEight) {
  const TriangleMesh mesh = generate_shape("figure_eight", {});
  const auto out = run_pipeline(mesh, "2%", "figure_eight");
  expect_certified(mesh, out);
  EXPECT_EQ(narrow_pieces(out), std::vector<int>{});
}

// A dumbbell with a long thin bar used to end in pieces of 51 mm^2 at 2%.
TEST(Pieces, NoCrumbOnAThinDumbbell) {
  const TriangleMesh mesh =
      generate_shape("dumbbell", {{"handle_radius", 0.15}, {"handle_length", 3.0}});
  const auto out = run_pipeline(mesh, "2%", "thin_dumbbell");
  expect_certified(mesh, out);
  expect_exact_seams(out);
  const double scale = out.report.at("result").at("mm_per_unit").get<double>();
  for (const auto& strip : out.flat.at("strips"))
    EXPECT_GE(flat_area_mm2(strip, scale), PaperSpec{}.min_area_mm2)
        << "flat strip " << strip.at("id");
}

// A separate part of the model smaller than min_area_mm2 (a sphere and, beside it, a
// tetrahedron with edges of 2.5 mm on paper) cannot be joined to anything: it stays, and the
// notes say it is a part by itself (what a larger print scale fixes), not that no neighbour
// takes it. The sphere's pieces are named in no note.
TEST(Pieces, ASmallSeparatePartIsNamedAsOne) {
  TriangleMesh mesh = generate_shape("sphere", {});
  const auto first = static_cast<int>(mesh.vertices.size());
  const double edge = 0.05;  // the sphere's radius is 1: the model 4.05 units long at 200 mm
  for (const Vec3& p : {Vec3(3, 0, 0), Vec3(3 + edge, 0, 0), Vec3(3, edge, 0), Vec3(3, 0, edge)})
    mesh.vertices.push_back(p);
  for (const std::array<int, 3>& t :
       std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}})
    mesh.triangles.push_back({first + t[0], first + t[1], first + t[2]});
  const auto out = run_pipeline(mesh, "2%", "sphere_and_speck");
  expect_certified(mesh, out);
  expect_exact_seams(out);
  int separate = 0;
  for (const auto& note : out.report.at("notes")) {
    const std::string text = note.get<std::string>();
    EXPECT_EQ(text.find("no neighbour takes it"), std::string::npos) << text;
    if (text.find("below min_area_mm2") == std::string::npos &&
        text.find("narrower than min_width_mm") == std::string::npos)
      continue;
    EXPECT_NE(text.find("a separate part of the model by itself"), std::string::npos) << text;
    ++separate;
  }
  EXPECT_EQ(separate, 2) << out.report.at("notes").dump();  // the speck: too small and too narrow
}

// Two boxes touching along an edge (diagonal neighbours in a grid): four faces on each of its
// segments, which the load used to refuse as non-manifold. It cuts them apart, box by box, and
// moves one box's copies of the edge's points into it by 1e-7 of the diagonal, so the two boxes'
// pieces share no seam: every seam edge has one partner of the same length, and the strips
// are certified against the boxes as given (the move is far under the bound's slack).
TEST(Pieces, TwoBoxesTouchingAlongAnEdgePrintAsTwoBoxes) {
  TriangleMesh mesh = box();
  const TriangleMesh second = box();
  const auto offset = static_cast<int>(mesh.vertices.size());
  for (const Vec3& p : second.vertices) mesh.vertices.push_back(p + Vec3(2.0, 1.5, 0.0));
  for (const auto& t : second.triangles)
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const auto out = run_pipeline(mesh, "2%", "touching_boxes");
  expect_certified(mesh, out);
  expect_exact_seams(out);
  EXPECT_NE(out.report.at("notes").dump().find("non-manifold edges apart"), std::string::npos)
      << out.report.at("notes").dump();
  const auto notes = out.report.at("notes").dump();
  EXPECT_EQ(notes.find("do not match"), std::string::npos) << notes;
  EXPECT_EQ(notes.find("no partner edge"), std::string::npos) << notes;
}

// Without limits the same run may keep small pieces: the bound is what removes them.
TEST(Pieces, LimitsOffKeepTheRefinementFree) {
  const TriangleMesh mesh =
      generate_shape("dumbbell", {{"handle_radius", 0.15}, {"handle_length", 3.0}});
  PaperSpec paper;
  paper.min_width_mm = 0.0;
  paper.min_area_mm2 = 0.0;
  const auto out = run_pipeline(mesh, "2%", "free_dumbbell", 0, default_config_text(), paper);
  expect_certified(mesh, out);
  expect_exact_seams(out);
}

// A cube of 12 triangles at 200 mm: each flat face is fanned from one of its own corners, and
// that fan's two triangles with two corners at the apex have no area. They used to stay in the
// strip, so the layout (which splits the 800 x 600 mm unfolding at inner edges to fit A4)
// printed 23 pieces, 11 of them nothing but a cut line with a tab on each side. Now every flat
// triangle has area, no boundary edge has zero length, and at most one piece per triangle.
TEST(Pieces, NoPieceWithoutAreaOnACube) {
  BoxOptions options;
  options.divisions_x = options.divisions_y = options.divisions_z = 1;
  const TriangleMesh mesh = box(options);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  const auto out = run_pipeline(mesh, "2%", "cube12");
  expect_certified(mesh, out);
  expect_exact_seams(out);
  const double scale = out.report.at("result").at("mm_per_unit").get<double>();
  std::size_t triangles = 0;
  for (const auto& strip : out.flat.at("strips")) {
    const auto& v2 = strip.at("vertices2d");
    auto at = [&](int i) -> Vec2 {
      return scale * Vec2(v2[i][0].get<double>(), v2[i][1].get<double>());
    };
    for (const auto& t : strip.at("triangles")) {
      const Vec2 a = at(t[0].get<int>()), b = at(t[1].get<int>()), c = at(t[2].get<int>());
      EXPECT_GT(0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x()), 1.0)
          << "flat strip " << strip.at("id") << " has a triangle without area";
      ++triangles;
    }
    for (const auto& e : strip.at("boundary"))
      EXPECT_GT((at(e.at("v1").get<int>()) - at(e.at("v0").get<int>())).norm(), 1.0)
          << "flat strip " << strip.at("id") << " has a zero-length boundary edge";
  }
  EXPECT_EQ(triangles, 12u);
  const auto pieces = nlohmann::json::parse(testing::read_text(out.dir / "pieces.json"));
  EXPECT_LE(pieces.at("pieces").size(), 12u);
  EXPECT_LE(out.report.at("result").at("pages").get<int>(), 12);  // 13 before
}

// libcgal-demo's cube.off (its own triangulation of the faces): the six faces cost six strips,
// and so did the cube whole, folded round; a tie used to keep it whole, cut into 6 strips that
// printed as 33 pieces. A tie keeps the faces: 6 parts, at most 12 pieces.
TEST(Pieces, ACubeWhoseWholeCostsAsMuchAsItsFacesKeepsItsFaces) {
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.vertices.emplace_back((k == 2 || k == 3 || k == 6 || k == 7) ? 1.0 : -1.0,
                               (k % 4 == 1 || k % 4 == 2) ? 1.0 : -1.0, k < 4 ? -1.0 : 1.0);
  mesh.triangles = {{0, 1, 3}, {3, 1, 2}, {0, 4, 1}, {1, 4, 5}, {3, 2, 7}, {7, 2, 6},
                    {4, 0, 3}, {7, 4, 3}, {6, 4, 7}, {6, 5, 4}, {1, 5, 6}, {2, 1, 6}};
  const auto out = run_pipeline(mesh, "2%", "cgal_cube");
  expect_certified(mesh, out);
  expect_exact_seams(out);
  EXPECT_EQ(out.report.at("result").at("segments").get<int>(), 6);
  const auto pieces = nlohmann::json::parse(testing::read_text(out.dir / "pieces.json"));
  EXPECT_LE(pieces.at("pieces").size(), 12u);
}

// Three meshes of libcgal-demo (installed by scripts/install-deps.sh), when present.
TEST(Pieces, ExactSeamsOnLibcgalDemoMeshes) {
  const std::filesystem::path archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!std::filesystem::exists(archive)) GTEST_SKIP() << "libcgal-demo is not installed";
  const auto dir = testing::fresh_temp_dir("cgal_meshes");
  const std::string command = "tar -xzf " + archive.string() + " -C " + dir.string() +
                              " data/meshes/eight.off data/meshes/cactus.off "
                              "data/meshes/pig.off";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  for (const char* name : {"eight", "cactus", "pig"}) {
    SCOPED_TRACE(name);
    const Mesh loaded = [&] {
      Mesh m;
      OpenMesh::IO::read_mesh(m, (dir / "data/meshes" / (std::string(name) + ".off")).string());
      return m;
    }();
    const auto out = run_pipeline(to_triangle_mesh(loaded), "2%", name);
    expect_exact_seams(out);
    const auto notes = out.report.at("notes").dump();
    EXPECT_EQ(notes.find("do not match"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("no partner edge"), std::string::npos) << notes;
  }
}

// libcgal-demo meshes (installed by scripts/install-deps.sh) unpacked into a fresh folder, read;
// empty when the package is missing.
std::map<std::string, TriangleMesh> libcgal_demo_meshes(const std::vector<std::string>& names) {
  std::map<std::string, TriangleMesh> meshes;
  const std::filesystem::path archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!std::filesystem::exists(archive)) return meshes;
  const auto dir = testing::fresh_temp_dir("cgal_meshes");
  std::string command = "tar -xzf " + archive.string() + " -C " + dir.string();
  for (const std::string& name : names) command += " data/meshes/" + name + ".off";
  if (std::system(command.c_str()) != 0) return meshes;
  for (const std::string& name : names) {
    Mesh m;
    OpenMesh::IO::read_mesh(m, (dir / "data/meshes" / (name + ".off")).string());
    meshes[name] = to_triangle_mesh(m);
  }
  return meshes;
}

// boeing at 2% used to hold strips between two loops matched the cheaper way round, turned
// inside out between them: 98 seam edges ran the same way as their partners'. Every seam edge
// now has one reversed partner.
TEST(Pieces, EveryPieceFacesOutOnLibcgalDemoMeshes) {
  const auto meshes = libcgal_demo_meshes({"boeing"});
  if (meshes.empty()) GTEST_SKIP() << "libcgal-demo is not installed";
  for (const auto& [name, mesh] : meshes) {
    SCOPED_TRACE(name);
    const auto out = run_pipeline(mesh, "2%", name);
    expect_exact_seams(out);
  }
}

// The distance from `at` to the edge (page mm).
double distance_to_edge(const PlacedEdge& edge, const Vec2& at) {
  const Vec2 d = edge.b - edge.a;
  const double t = std::clamp((at - edge.a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
  return (edge.a + t * d - at).norm();
}

// Two convex quadrilaterals overlap (more than touching): no edge of either separates them.
bool boxes_overlap(const std::array<Vec2, 4>& a, const std::array<Vec2, 4>& b) {
  for (const auto* p : {&a, &b})
    for (int i = 0; i < 4; ++i) {
      const Vec2 edge = (*p)[(i + 1) % 4] - (*p)[i];
      const Vec2 normal(-edge.y(), edge.x());
      double a_lo = 1e300, a_hi = -1e300, b_lo = 1e300, b_hi = -1e300;
      for (const Vec2& q : a)
        a_lo = std::min(a_lo, normal.dot(q)), a_hi = std::max(a_hi, normal.dot(q));
      for (const Vec2& q : b)
        b_lo = std::min(b_lo, normal.dot(q)), b_hi = std::max(b_hi, normal.dot(q));
      if (a_hi <= b_lo || b_hi <= a_lo) return false;
    }
  return true;
}

// dino at 2%: cones opened along a ruling leave slits whose two sides lie side by side, in
// the crowd of seams that meet at the cone's apex; the label of one side used to find no spot
// but over other text. The other side's label names such a slit alone now: it is printed once,
// at the slit (its seam, or the start of its leader, near every edge of the slit), and where a
// slit keeps both labels they are not over each other.
TEST(Pieces, OneLabelNamesASlitWhoseSidesHaveNoRoomForTwo) {
  const auto meshes = libcgal_demo_meshes({"dino"});
  if (meshes.empty()) GTEST_SKIP() << "libcgal-demo is not installed";
  const auto out = run_pipeline(meshes.at("dino"), "2%", "dino");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  const std::vector<FlatStrip> strips = read_flat_strips(out.flat.at("strips"));
  LayoutOptions options;
  options.scale = out.report.at("result").at("mm_per_unit").get<double>();
  const PatternLayout layout = layout_pages(strips, options);
  int once = 0, twins_over_each_other = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      std::map<std::string, std::vector<const Label*>> by_text;
      for (const Label& label : piece.labels) by_text[label.text].push_back(&label);
      std::set<std::string> slits;
      for (const PieceSeam& seam : piece.seams)
        if (seam.partner == piece.name) slits.insert(seam.label);
      for (const std::string& slit : slits) {
        const auto& labels = by_text[slit];
        if (labels.size() == 2) {
          twins_over_each_other += boxes_overlap(label_box(*labels[0]), label_box(*labels[1]));
          continue;
        }
        ASSERT_EQ(labels.size(), 1u) << "slit " << slit << " of piece " << piece.name;
        ++once;
        const Label& label = *labels[0];
        const Vec2 at = label.leader.empty() ? label.position : label.leader.front();
        for (const PlacedEdge& edge : piece.edges) {
          if (edge.label != slit) continue;
          EXPECT_LT(distance_to_edge(edge, at), 12.0) << "slit " << slit << " named far from it";
        }
      }
    }
  EXPECT_EQ(twins_over_each_other, 0);
  EXPECT_GT(once, 0) << "no slit of dino is named once: the case this test is for is gone";
}

// Every text printed on one page: piece numbers and seam labels.
std::vector<std::array<Vec2, 4>> page_text_boxes(const Page& page) {
  std::vector<std::array<Vec2, 4>> boxes;
  for (const auto* pieces : {&page.pieces, &page.joints})
    for (const PlacedPiece& piece : *pieces) {
      boxes.push_back(label_box(piece.number));
      for (const Label& label : piece.labels) boxes.push_back(label_box(label));
    }
  return boxes;
}

// dino at 2%: its crowded cone apexes left 8 pairs of texts over each other, the labels placed
// last finding every spot taken by those before. Placed again with the crowded ones first (and
// the piece number after the labels), every text on every page lies clear of the others.
TEST(Pieces, CrowdedLabelsPlacedFirstLeaveNoTextOverAnotherOnDino) {
  const auto meshes = libcgal_demo_meshes({"dino"});
  if (meshes.empty()) GTEST_SKIP() << "libcgal-demo is not installed";
  const auto out = run_pipeline(meshes.at("dino"), "2%", "dino");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  LayoutOptions options;
  options.scale = out.report.at("result").at("mm_per_unit").get<double>();
  const PatternLayout layout = layout_pages(read_flat_strips(out.flat.at("strips")), options);
  int texts = 0, overlapping = 0;
  for (const Page& page : layout.pages) {
    const auto boxes = page_text_boxes(page);
    texts += static_cast<int>(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        overlapping += boxes_overlap(boxes[i], boxes[j]);
  }
  EXPECT_GT(texts, 300);
  EXPECT_EQ(overlapping, 0);
}

// `text` with the node line `from` (of the default config) replaced by `to`.
std::string with_node_line(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "the default config's line " << from << " changed";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// `text` with cuts along the exact iso-lines (straighten_passes: 0): the merge's tests below
// were made for the pieces those cuts leave, which the straightened cuts no longer do.
std::string with_exact_isolines(const std::string& text) {
  return with_node_line(text, "{impl: cut.harmonic,      back: [select]}",
                        "{impl: cut.harmonic, params: {straighten_passes: 0}, back: [select]}");
}

// The default config with the merge's narrow joins off (narrow_join_share 1), cut along the
// exact iso-lines.
std::string without_narrow_joins() {
  return with_node_line(with_exact_isolines(default_config_text()),
                        "{impl: merge.congruent,   to: [layout]}",
                        "{impl: merge.congruent, params: {narrow_join_share: 1}, to: [layout]}");
}

// anchor_dense at 2% with the merge's narrow joins off (narrow_join_share: 1; femur, three_peaks
// and then anchor_dense itself lost the case as the merge learnt to fold or grow their narrow
// strips): a long thin strip is split where it bends, which saves a page, so the tries of the
// layout number their pieces differently; a piece arranged in an earlier try gets its labels
// back from there (pieces under another name). Its number must still print its own name, and
// every label must still name a seam of its piece, near that seam. The cuts and joins went on
// changing anchor_dense's pieces (the case was gone once the cut through a hole respected the
// limits and crumbs were hinged by the least slit), so the test lays out its flat strips as
// they were (tests/e2e/data, written by this test's pipeline run at 6813be8).
TEST(Pieces, LabelsArrangedInAnEarlierTryOfTheLayoutNameTheirOwnPieceAndSeam) {
  std::ifstream in(std::string(PAPERCRAFT_SOURCE_DIR) +
                   "/tests/e2e/data/anchor_dense_without_narrow_joins.json");
  ASSERT_TRUE(in) << "missing test data";
  const nlohmann::json model = nlohmann::json::parse(in);
  LayoutOptions options;
  options.scale = model.at("mm_per_unit").get<double>();
  const PatternLayout layout = layout_pages(read_flat_strips(model.at("strips")), options);
  bool split = false;
  for (const std::string& note : layout.warnings)
    split = split || note.rfind("long thin strips", 0) == 0;
  ASSERT_TRUE(split) << "no long strip of anchor_dense is split: the case this test is for is gone";
  int renamed = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      EXPECT_EQ(piece.number.text, piece.name);
      renamed += piece.name.find_first_not_of("0123456789") != std::string::npos;
      for (const Label& label : piece.labels) {
        const Vec2 at = label.leader.empty() ? label.position : label.leader.front();
        double nearest = 1e300;
        for (const PlacedEdge& edge : piece.edges)
          if (edge.label == label.text) nearest = std::min(nearest, distance_to_edge(edge, at));
        EXPECT_LT(nearest, 15.0) << "label " << label.text << " of piece " << piece.name;
      }
    }
  EXPECT_GT(renamed, 0);
}

// three_peaks at 2% printed 3 pieces narrower than 3 mm over 32-61% of their area: bands
// along its ridges and fans of long thin triangles, each with tabs on every side. The merge
// now folds such pieces out of a wider neighbour: run with that turned off
// (narrow_join_share: 1) and on, the narrow pieces fall to at most one and the pieces by a
// fifth, and the seams still meet exactly. (With the narrow joins off it now prints 2 narrow
// pieces, not 3: the crumbs are hinged where they leave the least slit, so the pieces the
// narrow joins start from differ.)
TEST(Pieces, NarrowStripsAreFoldedOutOfANeighbourOnThreePeaks) {
  const auto meshes = libcgal_demo_meshes({"three_peaks"});
  if (meshes.empty()) GTEST_SKIP() << "libcgal-demo is not installed";
  const auto before =
      run_pipeline(meshes.at("three_peaks"), "2%", "three_peaks", 0, without_narrow_joins());
  const auto after = run_pipeline(meshes.at("three_peaks"), "2%", "three_peaks", 0,
                                  with_exact_isolines(default_config_text()));
  ASSERT_TRUE(before.result.ok) << before.result.error;
  ASSERT_TRUE(after.result.ok) << after.result.error;
  EXPECT_GE(narrow_pieces(before).size(), 2u);
  EXPECT_LE(narrow_pieces(after).size(), 1u);
  EXPECT_LT(narrow_pieces(after).size(), narrow_pieces(before).size());
  EXPECT_LE(after.flat.at("strips").size(), 0.8 * before.flat.at("strips").size());
  expect_exact_seams(after);
}

// elephant-with-holes at 2% printed a piece on which several seams a few millimetres long meet
// in a knot of cut lines, where no leader line can leave the seams. Their labels are printed at
// the nearest clear spot instead: over no other text, and near their seam. The merge now folds
// that piece differently, so the test lays out the piece as it was (tests/e2e/data).
TEST(Pieces, LabelsNoLeaderReachesArePrintedClearNearTheirSeamOnElephantWithHoles) {
  std::ifstream in(std::string(PAPERCRAFT_SOURCE_DIR) +
                   "/tests/e2e/data/elephant_with_holes_strip_32.json");
  ASSERT_TRUE(in) << "missing test data";
  const nlohmann::json piece = nlohmann::json::parse(in);
  LayoutOptions options;
  options.scale = piece.at("mm_per_unit").get<double>();
  const PatternLayout layout = layout_pages(read_flat_strips(piece.at("strips")), options);
  // "piece 35: label A143 finds no spot ... printed near its seam"
  std::set<std::pair<std::string, std::string>> near_only;
  for (const std::string& note : layout.warnings) {
    if (note.find("printed near its seam") == std::string::npos) continue;
    const std::size_t colon = note.find(':'), label = note.find("label ");
    ASSERT_NE(colon, std::string::npos);
    ASSERT_NE(label, std::string::npos);
    near_only.insert(
        {note.substr(6, colon - 6), note.substr(label + 6, note.find(' ', label + 6) - label - 6)});
  }
  ASSERT_FALSE(near_only.empty())
      << "every label reaches a spot: the case this test is for is gone";
  int overlapping = 0, checked = 0;
  for (const Page& page : layout.pages) {
    const auto boxes = page_text_boxes(page);
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        overlapping += boxes_overlap(boxes[i], boxes[j]);
    for (const PlacedPiece& piece : page.pieces)
      for (const Label& label : piece.labels) {
        if (!near_only.count({piece.name, label.text})) continue;
        ++checked;
        EXPECT_TRUE(label.leader.empty());
        double nearest = 1e300;
        for (const PlacedEdge& edge : piece.edges)
          if (edge.label == label.text)
            nearest = std::min(nearest, distance_to_edge(edge, label.position));
        EXPECT_LT(nearest, 12.5) << "label " << label.text << " of piece " << piece.name;
      }
  }
  EXPECT_EQ(overlapping, 0);
  EXPECT_GE(checked, static_cast<int>(near_only.size()));
}

// couplingdown (libcgal-demo) at 2% printed narrow bands (120 and 139 mm^2, narrower than
// min_width_mm over 100% and 63% of their area) beside pieces whose every hinge laid them over
// their neighbours. The part of each and a neighbouring part, glued back along the cut that
// parted them, are one strip within the tolerance: the merge refines them together in 3D,
// certified, and the two print as one piece. (Cut along the exact iso-lines, which made those
// bands.)
TEST(Pieces, ANarrowPieceIsRefinedTogetherWithItsNeighbourInThreeD) {
  // Run as a user runs it (the OFF read in double precision, so the cuts are the command's).
  const std::filesystem::path archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!std::filesystem::exists(archive)) GTEST_SKIP() << "libcgal-demo is not installed";
  const auto dir = testing::fresh_temp_dir("cgal_couplingdown");
  const std::string unpack =
      "tar -xzf " + archive.string() + " -C " + dir.string() + " data/meshes/couplingdown.off";
  ASSERT_EQ(std::system(unpack.c_str()), 0) << unpack;
  const auto input = dir / "data/meshes/couplingdown.off";
  std::string config = with_exact_isolines(
      testing::read_text(std::filesystem::path(PAPERCRAFT_SOURCE_DIR) / "configs/default.yaml"));
  std::ofstream(dir / "exact.yaml") << config;
  const testing::CommandResult run =
      testing::run_command("run " + input.string() + " --tolerance 2% --threads 2 -q -c " +
                           (dir / "exact.yaml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  testing::PipelineOutput out;
  out.result.ok = true;
  out.dir = dir / "out" / "couplingdown";
  out.report = nlohmann::json::parse(testing::read_text(out.dir / "report.json"));
  out.strips = testing::read_strips_obj(out.dir / "approximation.obj");
  out.flat = nlohmann::json::parse(testing::read_text(out.dir / "strips.json"));
  expect_certified(to_triangle_mesh(load_mesh(input).mesh), out);
  expect_exact_seams(out);
  EXPECT_EQ(narrow_pieces(out), std::vector<int>{});
  const std::string notes = out.report.at("notes").dump();
  EXPECT_NE(notes.find("together with its neighbour's: glued along their cut, the two are one "
                       "strip within the tolerance"),
            std::string::npos)
      << notes;

  // Each join judged costs a merge of the whole model: with a budget of none, the join found
  // above is not judged, and a note says where the budget ran out.
  const std::string merge_line = "{impl: merge.congruent,   to: [layout]}";
  ASSERT_NE(config.find(merge_line), std::string::npos);
  config.replace(config.find(merge_line), merge_line.size(),
                 "{impl: merge.congruent, params: {most_rejoin_trials: 0}, to: [layout]}");
  std::ofstream(dir / "budget.yaml") << config;
  const testing::CommandResult budget =
      testing::run_command("run " + input.string() + " --tolerance 2% --threads 2 -q -c " +
                           (dir / "budget.yaml").string() + " -o " + (dir / "budget").string());
  ASSERT_EQ(budget.exit_code, 0) << budget.output;
  const nlohmann::json budget_notes =
      nlohmann::json::parse(testing::read_text(dir / "budget/couplingdown/report.json"))
          .at("notes");
  int joined = 0, stopped = 0;
  for (const auto& note : budget_notes) {
    const std::string text = note.get<std::string>();
    joined += text.find("together with its neighbour's") != std::string::npos;
    stopped +=
        text.find("joins in 3D: stopped after 0 merges of the whole model") != std::string::npos;
  }
  EXPECT_EQ(joined, 0) << budget_notes.dump();
  EXPECT_EQ(stopped, 1) << budget_notes.dump();
}

}  // namespace
}  // namespace papercraft
