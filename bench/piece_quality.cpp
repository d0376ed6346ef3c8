// Whether a person can cut and glue what a run printed: reads <model>/strips.json and
// <model>/report.json of finished runs and prints, per model, the pieces narrower than a
// fold-able width over much of their area, the pieces smaller than a fingertip, and every way a
// seam can fail to meet (tests/support/pattern_checks.h), then the totals. "narrow alone" and
// "small alone" count those that are a separate part of the input by themselves (a narrow
// strip glued to no other, a small one whose whole part is under the area bound): no join
// can widen or grow them. "slivers" counts the pieces holding one connected
// region narrower than --narrow-mm of more than --sliver-mm2, whatever its share of the piece:
// a thin band glued on along a large piece. "self seams" counts the labels of seams of a piece
// with itself (a closed strip opened along a ruling, and a piece hinged onto a neighbour along
// one edge of a longer shared chain: the chain's other edges), "most self" the most on one
// piece (in the totals, the most on any piece): a cluster of them is a tangle of short seams,
// each with its label, to glue by hand.
//
//   piece_quality OUT/eight OUT/cactus ...            # model folders
//   piece_quality --narrow-mm 3 --narrow-share 0.25 --small-mm2 100 --sliver-mm2 100 OUT/*/
//   piece_quality --list OUT/*/ 2>&1 >/dev/null   # each narrow or small piece, on stderr:
//     its area, narrow share, neighbours and whole part; the neighbours whose seam with it runs
//     round a saddle of the surface (widest_corner_round_a_seam_vertex over 360 degrees), and
//     those it lies flat beside folded out of them over one shared edge (folds_flat_onto: a
//     hinge in the plane could take it); last, how many of those glued to another could.
//
// Exit status 0 (findings are data), 2 for a bad command line or unreadable folder.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/flat_boundary.h"
#include "support/flat_strips_json.h"
#include "support/pattern_checks.h"

namespace {

// The labels of seams of each strip with itself: their number over the model, and the most on
// one strip.
std::pair<long, long> self_seams(const nlohmann::json& strips) {
  long all = 0, most = 0;
  for (const auto& strip : strips) {
    const int id = strip.at("id").get<int>();
    std::set<std::string> labels;
    for (const auto& edge : strip.at("boundary"))
      if (edge.at("kind") == "seam" && edge.at("neighbour").get<int>() == id)
        labels.insert(edge.at("label").get<std::string>());
    all += static_cast<long>(labels.size());
    most = std::max(most, static_cast<long>(labels.size()));
  }
  return {all, most};
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return nlohmann::json::parse(in);
}

int count_notes(const nlohmann::json& report, const std::string& text) {
  int count = 0;
  for (const auto& note : report.value("notes", nlohmann::json::array()))
    count += note.get<std::string>().find(text) != std::string::npos;
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  using papercraft::BoundaryEdge;
  using papercraft::FlatStrip;
  double narrow_mm = 3.0, narrow_share = 0.25, small_mm2 = 100.0, sliver_mm2 = 100.0;
  bool list = false;
  std::vector<std::filesystem::path> models;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> double {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", arg.c_str());
        std::exit(2);
      }
      return std::atof(argv[++i]);
    };
    if (arg == "--narrow-mm")
      narrow_mm = value();
    else if (arg == "--narrow-share")
      narrow_share = value();
    else if (arg == "--small-mm2")
      small_mm2 = value();
    else if (arg == "--sliver-mm2")
      sliver_mm2 = value();
    else if (arg == "--list")
      list = true;
    else if (arg.rfind("--", 0) == 0) {
      std::fprintf(stderr, "unknown option %s\n", arg.c_str());
      return 2;
    } else
      models.emplace_back(arg);
  }
  if (models.empty()) {
    std::fprintf(stderr,
                 "usage: piece_quality [--narrow-mm 3] [--narrow-share 0.25] "
                 "[--small-mm2 100] [--sliver-mm2 100] [--list] MODEL_DIR...\n");
    return 2;
  }
  std::printf(
      "| model | pieces | narrow | narrow alone | small | small alone | seam edges | no partner | "
      "length differs | other label | labels | not two chains | sides differ | "
      "notes unmatched | slivers | self seams | most self |\n");
  std::printf(
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  long total[16] = {};
  long beside = 0, hinged = 0;  // with --list: short pieces glued to another; of them, foldable
  for (const auto& dir : models) {
    nlohmann::json strips, report;
    try {
      strips = read_json(dir / "strips.json").at("strips");
      report = read_json(dir / "report.json");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", dir.string().c_str(), e.what());
      return 2;
    }
    const double mm_per_unit = report.at("result").at("mm_per_unit").get<double>();
    const auto pieces = papercraft::testing::check_pieces(strips, mm_per_unit, narrow_mm,
                                                          narrow_share, small_mm2, sliver_mm2);
    const auto seams = papercraft::testing::check_seams(strips);
    const int unmatched_notes =
        count_notes(report, "ends do not match") + count_notes(report, "has no partner edge");
    const auto [self, most_self] = self_seams(strips);
    const long row[16] = {pieces.pieces,
                          pieces.narrow,
                          pieces.narrow_alone,
                          pieces.small,
                          pieces.small_alone,
                          seams.seam_edges,
                          seams.edges_without_one_partner,
                          seams.edges_of_other_length,
                          seams.edges_with_other_label,
                          seams.labels,
                          seams.labels_not_two_chains,
                          seams.labels_with_sides_differing,
                          unmatched_notes,
                          pieces.slivers,
                          self,
                          most_self};
    for (int k = 0; k < 15; ++k) total[k] += row[k];
    total[15] = std::max(total[15], row[15]);
    std::printf(
        "| %s | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld "
        "| %ld | %ld |\n",
        dir.filename().empty() ? dir.parent_path().filename().c_str() : dir.filename().c_str(),
        row[0], row[1], row[2], row[3], row[4], row[5], row[6], row[7], row[8], row[9], row[10],
        row[11], row[12], row[13], row[14], row[15]);
    for (const auto& p : pieces.problems) std::fprintf(stderr, "%s: %s\n", dir.c_str(), p.c_str());
    if (list) {
      std::map<long, FlatStrip> by_id;
      for (FlatStrip& strip : papercraft::testing::read_flat_strips(strips))
        by_id[strip.id] = std::move(strip);
      for (const auto& p : pieces.shorts) {
        std::ostringstream saddles;  // neighbours whose seam with it runs round a saddle
        std::ostringstream folds;    // neighbours a hinge over one edge lays it flat onto
        const FlatStrip& strip = by_id.at(p.id);
        std::set<long> seen;
        for (const BoundaryEdge& edge : strip.boundary) {
          const long n = edge.neighbour_strip;
          if (n < 0 || n == p.id || !seen.insert(n).second || !by_id.count(n)) continue;
          const double widest = papercraft::widest_corner_round_a_seam_vertex(strip, by_id.at(n));
          if (widest > 360.5) saddles << " " << n << " (" << std::lround(widest) << " deg)";
          if (papercraft::folds_flat_onto(strip, by_id.at(n))) folds << " " << n;
        }
        if (p.neighbours > 0) {
          ++beside;
          hinged += !folds.str().empty();
        }
        std::fprintf(
            stderr,
            "%s: short strip %ld: %.0f mm^2, %.0f%% narrower than %g mm, glued to %d "
            "other strips; its part of the model: %.0f mm^2 in %d strips%s%s%s%s\n",
            dir.c_str(), p.id, p.area_mm2, 100.0 * p.narrow_share, narrow_mm, p.neighbours,
            p.part_mm2, p.part_strips,
            saddles.str().empty() ? "" : "; seam round a saddle with:", saddles.str().c_str(),
            p.neighbours == 0 ? ""
            : folds.str().empty()
                ? "; folded out of any neighbour over any edge they share, it overlaps it"
                : "; lies flat folded onto:",
            folds.str().c_str());
      }
    }
    for (const auto& p : seams.problems) std::fprintf(stderr, "%s: %s\n", dir.c_str(), p.c_str());
  }
  if (list)
    std::fprintf(stderr,
                 "narrow or small pieces glued to another: %ld; of them, lying flat folded onto a "
                 "neighbour over one seam edge: %ld\n",
                 beside, hinged);
  std::printf(
      "| **total** | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld | %ld "
      "| %ld | %ld | %ld |\n",
      total[0], total[1], total[2], total[3], total[4], total[5], total[6], total[7], total[8],
      total[9], total[10], total[11], total[12], total[13], total[14], total[15]);
  return 0;
}
