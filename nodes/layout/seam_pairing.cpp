// Seam pairing: seam edges matched to their partners, gathered into chains, chains paired.
#include "nodes/layout/seam_pairing.h"

#include <limits>
#include <map>
#include <utility>

namespace papercraft::layout_internal {

SeamEdges match_seam_edges(const std::vector<Piece>& pieces, const std::vector<StripData>& strips) {
  using Key = std::pair<std::string, std::array<double, 6>>;
  auto key = [](const std::string& label, const Vec3& a, const Vec3& b) {
    return Key{label, {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}};
  };
  SeamEdges seams;
  std::map<Key, std::vector<int>> by_key;
  seams.id.resize(pieces.size());
  for (int p = 0; p < static_cast<int>(pieces.size()); ++p) {
    const FlatStrip& strip = *strips[pieces[p].strip].strip;
    seams.id[p].resize(pieces[p].loops.size());
    for (int l = 0; l < static_cast<int>(pieces[p].loops.size()); ++l) {
      const auto& loop = pieces[p].loops[l];
      seams.id[p][l].assign(loop.size(), -1);
      for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
        if (loop[i].kind != EdgeKind::Seam) continue;
        const int id = static_cast<int>(seams.refs.size());
        seams.refs.push_back({p, l, i});
        seams.id[p][l][i] = id;
        by_key[key(loop[i].label, strip.vertices3d[loop[i].v0], strip.vertices3d[loop[i].v1])]
            .push_back(id);
      }
    }
  }
  seams.partner.assign(seams.refs.size(), -1);
  for (int e = 0; e < static_cast<int>(seams.refs.size()); ++e) {
    if (seams.partner[e] >= 0) continue;
    const auto [p, l, i] = seams.refs[e];
    const PieceEdge& edge = pieces[p].loops[l][i];
    const FlatStrip& strip = *strips[pieces[p].strip].strip;
    auto it = by_key.find(key(edge.label, strip.vertices3d[edge.v1], strip.vertices3d[edge.v0]));
    if (it == by_key.end()) continue;
    for (int f : it->second)
      if (f != e && seams.partner[f] < 0) {
        seams.partner[e] = f;
        seams.partner[f] = e;
        break;
      }
  }
  return seams;
}

std::vector<Chain> seam_chains(const std::vector<Piece>& pieces,
                               const std::vector<StripData>& strips, const SeamEdges& seams,
                               double tolerance3d) {
  std::vector<Chain> chains;
  for (int p = 0; p < static_cast<int>(pieces.size()); ++p) {
    const Piece& piece = pieces[p];
    const FlatStrip& strip = *strips[piece.strip].strip;
    for (int l = 0; l < static_cast<int>(piece.loops.size()); ++l) {
      const std::vector<PieceEdge>& loop = piece.loops[l];
      const int n = static_cast<int>(loop.size());
      auto joins = [&](int i) {
        const int a = i, b = (i + 1) % n;
        const int ea = seams.id[p][l][a], eb = seams.id[p][l][b];
        if (ea < 0 || eb < 0 || loop[a].label != loop[b].label) return false;
        const int pa = seams.partner[ea], pb = seams.partner[eb];
        if (pa >= 0 && pb >= 0) {
          if (pb == ea) return false;  // the two sides of an opened cone apex
          const auto& ra = seams.refs[pa];
          const auto& rb = seams.refs[pb];
          const int m = static_cast<int>(pieces[ra[0]].loops[ra[1]].size());
          // Consecutive the other way round, or the same way where the partners run the same
          // way (pieces of opposite orientation; the labels already say they are one chain).
          return rb[0] == ra[0] && rb[1] == ra[1] &&
                 (rb[2] == (ra[2] + m - 1) % m || rb[2] == (ra[2] + 1) % m);
        }
        if (pa >= 0 || pb >= 0) return false;
        // Unmatched: one chain unless the second edge comes straight back in 3D.
        return (strip.vertices3d[loop[b].v1] - strip.vertices3d[loop[a].v0]).norm() > tolerance3d;
      };
      auto make = [&](int start, int count, bool closed) {
        Chain c;
        c.piece = p;
        c.loop = l;
        c.start = start;
        c.count = count;
        c.closed = closed;
        c.label = loop[start].label;
        c.first = strip.vertices3d[loop[start].v0];
        c.last = strip.vertices3d[loop[(start + count - 1) % n].v1];
        c.partner_edge = seams.partner[seams.id[p][l][start]];
        chains.push_back(c);
      };
      bool all = true;
      for (int i = 0; i < n && all; ++i) all = joins(i);
      if (all) {
        make(0, n, true);
        continue;
      }
      for (int i = 0; i < n; ++i) {
        if (loop[i].kind != EdgeKind::Seam || joins((i + n - 1) % n)) continue;
        int count = 1;
        while (joins((i + count - 1) % n)) ++count;
        make(i, count, false);
      }
    }
  }
  return chains;
}

std::vector<SeamPair> pair_chains(const std::vector<Chain>& chains, const SeamEdges& seams,
                                  const std::vector<Piece>& pieces, double tolerance3d,
                                  std::vector<std::string>& warnings) {
  std::vector<int> chain_of_edge(seams.refs.size(), -1);
  for (int c = 0; c < static_cast<int>(chains.size()); ++c) {
    const Chain& chain = chains[c];
    const int n = static_cast<int>(pieces[chain.piece].loops[chain.loop].size());
    for (int i = 0; i < chain.count; ++i)
      chain_of_edge[seams.id[chain.piece][chain.loop][(chain.start + i) % n]] = c;
  }
  std::map<std::string, std::vector<SeamPair>> by_label;
  std::vector<bool> paired(chains.size(), false);
  for (int c = 0; c < static_cast<int>(chains.size()); ++c) {
    if (paired[c] || chains[c].partner_edge < 0) continue;
    const int d = chain_of_edge[chains[c].partner_edge];
    if (d < 0 || d == c || paired[d]) continue;
    paired[c] = paired[d] = true;
    by_label[chains[c].label].push_back({c, d, chains[c].label});
  }
  // Edges without an exact partner (a neighbour with extra vertices on the seam): pair
  // whole chains of one label by their nearest ends.
  std::map<std::string, std::vector<int>> unpaired;
  for (int c = 0; c < static_cast<int>(chains.size()); ++c)
    if (!paired[c]) unpaired[chains[c].label].push_back(c);
  for (const auto& [label, members] : unpaired) {
    std::vector<bool> taken(members.size(), false);
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (taken[i]) continue;
      taken[i] = true;
      const Chain& a = chains[members[i]];
      int best = -1;
      double best_error = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < members.size(); ++j) {
        if (taken[j]) continue;
        const Chain& b = chains[members[j]];
        const double error = (a.first - b.last).norm() + (a.last - b.first).norm();
        if (error < best_error) {
          best_error = error;
          best = static_cast<int>(j);
        }
      }
      if (best < 0) {
        warnings.push_back("seam " + label + " has no partner edge; its tab is glued by eye");
        by_label[label].push_back({members[i], -1, label});
        continue;
      }
      taken[best] = true;
      if (members.size() > 2 && best_error > 2 * tolerance3d)
        warnings.push_back("seam " + label + " is used by " + std::to_string(members.size()) +
                           " edge chains whose ends do not match; paired by nearest ends");
      by_label[label].push_back({members[i], members[best], label});
    }
  }
  std::vector<SeamPair> pairs;
  for (auto& [label, these] : by_label) {
    if (these.size() > 1)
      for (std::size_t k = 0; k < these.size(); ++k)
        these[k].printed = label + "." + std::to_string(k + 1);
    pairs.insert(pairs.end(), these.begin(), these.end());
  }
  return pairs;
}

double chain_length(const StripData& data, const Piece& piece, const Chain& chain) {
  const auto& loop = piece.loops[chain.loop];
  double length = 0;
  for (int i = 0; i < chain.count; ++i) {
    const PieceEdge& e = loop[(chain.start + i) % loop.size()];
    length += (data.points[e.v1] - data.points[e.v0]).norm();
  }
  return length;
}

}  // namespace papercraft::layout_internal
