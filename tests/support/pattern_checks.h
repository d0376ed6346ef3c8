#pragma once
// Independent checks of a pattern as strips.json describes it (DESIGN.md section 4), for the
// tests and for bench/piece_quality: seams glued edge to edge with equal lengths and one label
// per chain on both sides, piece sizes and widths on paper. Reads only the JSON, never the
// structures that made it.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/piece_width.h"
#include "core/union_find.h"

namespace papercraft::testing {

struct SeamFindings {
  int seam_edges = 0;
  int edges_without_one_partner = 0;  // not exactly one seam edge with the same 3D ends
  int edges_of_other_length = 0;      // partner's flat length differs by more than 1e-9 rel.
  int edges_with_other_label = 0;     // partner carries another label or names another strip
  int labels = 0;
  int labels_not_two_chains = 0;  // a label whose edges are not one chain on each of two sides
  int labels_with_sides_differing = 0;  // a label whose two sides differ in flat length or edges
  std::vector<std::string> problems;    // the first few, for messages

  bool exact() const {
    return edges_without_one_partner == 0 && edges_of_other_length == 0 &&
           edges_with_other_label == 0 && labels_not_two_chains == 0 &&
           labels_with_sides_differing == 0;
  }
};

namespace detail {

inline std::array<double, 3> point3(const nlohmann::json& strip, int v) {
  const auto& p = strip.at("vertices3d").at(v);
  return {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>()};
}

inline double flat_length(const nlohmann::json& strip, int a, int b) {
  const auto& p = strip.at("vertices2d").at(a);
  const auto& q = strip.at("vertices2d").at(b);
  return std::hypot(p.at(0).get<double>() - q.at(0).get<double>(),
                    p.at(1).get<double>() - q.at(1).get<double>());
}

}  // namespace detail

/// Seams of strips.json's "strips": every seam edge glued to exactly one edge with the same
/// 3D end points (running the other way), of the same flat length, with the same label; each
/// label one chain of consecutive edges on each of its two sides (or on the two sides of one
/// strip's own seam).
inline SeamFindings check_seams(const nlohmann::json& strips) {
  SeamFindings findings;
  struct Edge {
    int strip;
    int index;
    int v0, v1;
    std::string label;
    int neighbour;
  };
  std::vector<Edge> edges;
  std::map<int, int> strip_of_id;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    strip_of_id[strips[s].at("id").get<int>()] = s;
  using Key = std::array<double, 6>;
  std::map<Key, std::vector<int>> by_ends;  // directed: v0 then v1
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    const auto& boundary = strips[s].at("boundary");
    for (int e = 0; e < static_cast<int>(boundary.size()); ++e) {
      const auto& b = boundary[e];
      if (b.at("kind").get<std::string>() != "seam") continue;
      Edge edge{s,
                e,
                b.at("v0").get<int>(),
                b.at("v1").get<int>(),
                b.value("label", std::string()),
                b.value("neighbour", -1)};
      const auto p = detail::point3(strips[s], edge.v0), q = detail::point3(strips[s], edge.v1);
      by_ends[{p[0], p[1], p[2], q[0], q[1], q[2]}].push_back(static_cast<int>(edges.size()));
      edges.push_back(edge);
    }
  }
  findings.seam_edges = static_cast<int>(edges.size());
  auto problem = [&](const std::string& text) {
    if (findings.problems.size() < 8) findings.problems.push_back(text);
  };
  auto name = [&](const Edge& e) {
    return "strip " + strips[e.strip].at("id").dump() + " edge " + std::to_string(e.index) + " (" +
           e.label + ")";
  };
  std::vector<int> partner(edges.size(), -1);
  for (int g = 0; g < static_cast<int>(edges.size()); ++g) {
    const Edge& e = edges[g];
    const auto p = detail::point3(strips[e.strip], e.v0), q = detail::point3(strips[e.strip], e.v1);
    const auto it = by_ends.find({q[0], q[1], q[2], p[0], p[1], p[2]});
    const int count = it == by_ends.end() ? 0 : static_cast<int>(it->second.size());
    if (count != 1) {
      ++findings.edges_without_one_partner;
      problem(name(e) + " has " + std::to_string(count) + " partner edges");
      continue;
    }
    partner[g] = it->second.front();
    const Edge& o = edges[partner[g]];
    const double a = detail::flat_length(strips[e.strip], e.v0, e.v1);
    const double b = detail::flat_length(strips[o.strip], o.v0, o.v1);
    if (std::abs(a - b) > 1e-9 * std::max(a, b)) {
      ++findings.edges_of_other_length;
      problem(name(e) + " is " + std::to_string(a) + " long, its partner " + std::to_string(b));
    }
    const int neighbour_id = strips[o.strip].at("id").get<int>();
    if (o.label != e.label || e.neighbour != neighbour_id) {
      ++findings.edges_with_other_label;
      problem(name(e) + " is glued to " + name(o) + " (neighbour " + std::to_string(e.neighbour) +
              ")");
    }
  }
  // Chains: per label, the edges of each strip must form one run of consecutive boundary
  // edges (v1 of one is v0 of the next), and the label must have two sides.
  std::map<std::string, std::vector<int>> by_label;
  for (int g = 0; g < static_cast<int>(edges.size()); ++g) by_label[edges[g].label].push_back(g);
  findings.labels = static_cast<int>(by_label.size());
  for (const auto& [label, members] : by_label) {
    // Sides: the label's edges joined where one ends where the next starts on the same strip,
    // but never an edge to its own partner (a cone's opened ruling: both sides meet at the
    // apex). Exactly two sides, each one run, glued to each other.
    std::map<int, int> side_of;
    for (std::size_t i = 0; i < members.size(); ++i) side_of[members[i]] = static_cast<int>(i);
    std::vector<int> parent(members.size());
    for (std::size_t i = 0; i < members.size(); ++i) parent[i] = static_cast<int>(i);
    auto root = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for (int g : members)
      for (int h : members) {
        if (g == h || edges[g].strip != edges[h].strip || edges[g].v1 != edges[h].v0) continue;
        if (partner[g] == h) continue;
        parent[root(side_of[g])] = root(side_of[h]);
      }
    std::set<int> sides;
    for (int g : members) sides.insert(root(side_of[g]));
    bool chains_ok = sides.size() == 2;
    for (int g : members)
      if (partner[g] >= 0 && side_of.count(partner[g]) &&
          root(side_of[g]) == root(side_of[partner[g]]))
        chains_ok = false;
    std::set<int> strips_of_label;
    for (int g : members) strips_of_label.insert(edges[g].strip);
    if (!chains_ok) {
      ++findings.labels_not_two_chains;
      problem("label " + label + " spans " + std::to_string(strips_of_label.size()) +
              " strips in " + std::to_string(sides.size()) + " chains");
    }
    // Both sides: the partners of the label's edges are exactly its edges (so the label's
    // edges pair up across the seam), each of the same flat length as its partner.
    bool sides_ok = true;
    std::set<int> member_set(members.begin(), members.end());
    std::map<int, double> length;  // per strip, for the message
    for (int g : members) {
      const Edge& e = edges[g];
      const double a = detail::flat_length(strips[e.strip], e.v0, e.v1);
      length[e.strip] += a;
      if (partner[g] < 0 || member_set.count(partner[g]) == 0) {
        sides_ok = false;
        continue;
      }
      const Edge& o = edges[partner[g]];
      const double b = detail::flat_length(strips[o.strip], o.v0, o.v1);
      if (std::abs(a - b) > 1e-9 * std::max(a, b)) sides_ok = false;
    }
    if (!sides_ok) {
      ++findings.labels_with_sides_differing;
      std::string sides;
      for (const auto& [strip, total] : length)
        sides.append(" ").append(strips[strip].at("id").dump()).append(":").append(
            std::to_string(total));
      problem("label " + label + " has sides that differ (length per strip" + sides + ")");
    }
  }
  return findings;
}

struct PieceFindings {
  int pieces = 0;
  int narrow = 0;  // more than `narrow_share` of the area narrower than `narrow_mm`
  int small = 0;   // less than `small_mm2`
  /// Of the small ones, those whose whole piece of the model (the strips joined to them by
  /// seams, transitively) is under `small_mm2` too: a separate part of the input that small,
  /// with no neighbour to join.
  int small_alone = 0;
  /// Of the narrow ones, those that are a whole piece of the model on their own (no seam to
  /// another strip): a separate part of the input that thin, with no neighbour to join.
  int narrow_alone = 0;
  /// Pieces holding one connected region narrower than `narrow_mm` of more than `sliver_mm2`
  /// (largest_narrow_region): a band glued on along a wider piece, or running out of one,
  /// which the share does not show when the piece is large.
  int slivers = 0;
  double smallest_mm2 = 0.0;
  double most_narrow_share = 0.0;
  std::vector<std::string> problems;
  /// Every piece counted narrow or small, with what decides whether a join could help it.
  struct Short {
    long id = 0;
    double area_mm2 = 0.0;
    double narrow_share = 0.0;  // of its area narrower than `narrow_mm`
    int neighbours = 0;         // other strips it has a seam with
    double part_mm2 = 0.0;      // its whole piece of the model (strips joined by seams)
    int part_strips = 0;
  };
  std::vector<Short> shorts;
};

/// Sizes on paper of the flat strips (model units times `mm_per_unit`).
inline PieceFindings check_pieces(const nlohmann::json& strips, double mm_per_unit,
                                  double narrow_mm = 3.0, double narrow_share = 0.25,
                                  double small_mm2 = 100.0, double sliver_mm2 = 100.0) {
  PieceFindings findings;
  findings.smallest_mm2 = 1e300;
  // Strips joined by seams, by index.
  std::map<long, std::size_t> index_of;
  for (std::size_t i = 0; i < strips.size(); ++i) index_of[strips[i].at("id").get<long>()] = i;
  UnionFind joined(strips.size());
  for (std::size_t i = 0; i < strips.size(); ++i)
    for (const auto& edge : strips[i].at("boundary")) {
      auto it = index_of.find(edge.value("neighbour", -1L));
      if (it != index_of.end()) joined.unite(i, it->second);
    }
  std::vector<double> areas(strips.size(), 0.0), shares(strips.size(), 0.0);
  std::vector<bool> narrow(strips.size(), false);
  for (std::size_t s = 0; s < strips.size(); ++s) {
    const auto& strip = strips[s];
    std::vector<Vec2> points;
    for (const auto& p : strip.at("vertices2d"))
      points.emplace_back(p.at(0).get<double>() * mm_per_unit, p.at(1).get<double>() * mm_per_unit);
    std::vector<Triangle> triangles;
    double area = 0.0;
    for (const auto& t : strip.at("triangles")) {
      const Triangle tri{t.at(0).get<int>(), t.at(1).get<int>(), t.at(2).get<int>()};
      triangles.push_back(tri);
      const Vec2 u = points[tri[1]] - points[tri[0]], v = points[tri[2]] - points[tri[0]];
      area += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
    }
    ++findings.pieces;
    areas[s] = area;
    findings.smallest_mm2 = std::min(findings.smallest_mm2, area);
    NarrowRaster raster;
    const double sliver = largest_narrow_region(points, triangles, narrow_mm, {}, &raster);
    const double share = raster.fraction();
    shares[s] = share;
    findings.most_narrow_share = std::max(findings.most_narrow_share, share);
    const std::string id = strip.at("id").dump();
    if (share > narrow_share) {
      ++findings.narrow;
      narrow[s] = true;
      if (findings.problems.size() < 8)
        findings.problems.push_back("strip " + id + ": " + std::to_string(int(share * 100)) +
                                    "% narrower than " + std::to_string(narrow_mm) + " mm");
    }
    if (sliver > sliver_mm2) {
      ++findings.slivers;
      if (findings.problems.size() < 8)
        findings.problems.push_back("strip " + id + ": a region narrower than " +
                                    std::to_string(narrow_mm) + " mm of over " +
                                    std::to_string(sliver_mm2) + " mm^2");
    }
    if (area < small_mm2) {
      ++findings.small;
      if (findings.problems.size() < 8)
        findings.problems.push_back("strip " + id + ": " + std::to_string(area) + " mm^2");
    }
  }
  std::map<std::size_t, double> component_area;
  for (std::size_t s = 0; s < strips.size(); ++s) component_area[joined.find(s)] += areas[s];
  std::map<std::size_t, int> component_strips;
  for (std::size_t s = 0; s < strips.size(); ++s) ++component_strips[joined.find(s)];
  for (std::size_t s = 0; s < strips.size(); ++s) {
    findings.small_alone += areas[s] < small_mm2 && component_area[joined.find(s)] < small_mm2;
    findings.narrow_alone += narrow[s] && component_strips[joined.find(s)] == 1;
    if (narrow[s] || areas[s] < small_mm2) {
      std::set<long> others;
      const long id = strips[s].at("id").get<long>();
      for (const auto& edge : strips[s].at("boundary")) {
        const long neighbour = edge.value("neighbour", -1L);
        if (neighbour >= 0 && neighbour != id) others.insert(neighbour);
      }
      findings.shorts.push_back({id, areas[s], shares[s], static_cast<int>(others.size()),
                                 component_area[joined.find(s)], component_strips[joined.find(s)]});
    }
  }
  if (findings.pieces == 0) findings.smallest_mm2 = 0.0;
  return findings;
}

}  // namespace papercraft::testing
