#include "core/build_order.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <queue>
#include <string>
#include <tuple>

#include "core/errors.h"
#include "core/flat_boundary.h"

namespace papercraft {

namespace {

// One seam label between two pieces, and its length on paper.
struct LabelledSeam {
  std::string label;
  double length_mm = 0.0;
};

// Everything two pieces share: every seam label between them and their summed length.
struct Neighbour {
  int piece = -1;
  double length_mm = 0.0;
  std::vector<LabelledSeam> seams;
};

// The piece graph of a layout: printed pieces in number order, their areas on paper, the
// seams between them and the seams of each piece with itself.
struct PieceGraph {
  std::vector<std::string> names;
  std::vector<double> areas;
  std::vector<std::vector<Neighbour>> neighbours;  // by piece index, ascending
  std::vector<std::vector<LabelledSeam>> self_seams;
};

// Lengths (mm) and areas (mm²) to a thousandth: what differs by less is a tie, broken by
// number, so rounding in the layout cannot reorder alike pieces.
long long rounded(double value) {
  return std::llround(value * 1000.0);
}

bool longer_first(const LabelledSeam& a, const LabelledSeam& b) {
  if (rounded(a.length_mm) != rounded(b.length_mm)) return a.length_mm > b.length_mm;
  return a.label < b.label;
}

// Seam length on paper by printed label, over the piece's seam edges.
std::map<std::string, double> seam_lengths(const PlacedPiece& piece) {
  std::map<std::string, double> lengths;
  for (const PlacedEdge& edge : piece.edges)
    if (edge.kind == EdgeKind::Seam && !edge.label.empty())
      lengths[edge.label] += (edge.b - edge.a).norm();
  return lengths;
}

PieceGraph piece_graph(const PatternLayout& layout) {
  std::vector<const PlacedPiece*> pieces;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) pieces.push_back(&piece);
  std::stable_sort(pieces.begin(), pieces.end(), [](const PlacedPiece* a, const PlacedPiece* b) {
    return piece_name_less(a->name, b->name);
  });
  PieceGraph graph;
  std::map<std::string, int> index;
  for (const PlacedPiece* piece : pieces) {
    if (!index.emplace(piece->name, static_cast<int>(graph.names.size())).second)
      throw InvalidInputException("two printed pieces are named '" + piece->name +
                                  "': piece names must be unique for a build order");
    graph.names.push_back(piece->name);
    graph.areas.push_back(flat_area(piece->vertices, piece->triangles));
  }
  const int n = static_cast<int>(pieces.size());
  graph.neighbours.resize(n);
  graph.self_seams.resize(n);
  // Each label between two pieces once, with the lengths its sides have on paper (equal up to
  // rounding: the unfolding is isometric).
  std::map<std::tuple<int, int, std::string>, std::vector<double>> sides;
  for (int p = 0; p < n; ++p) {
    const std::map<std::string, double> lengths = seam_lengths(*pieces[p]);
    std::map<std::pair<std::string, int>, bool> seen;
    for (const PieceSeam& seam : pieces[p]->seams) {
      const auto partner = index.find(seam.partner);
      if (seam.label.empty() || partner == index.end()) continue;
      const int q = partner->second;
      if (!seen.emplace(std::make_pair(seam.label, q), true).second) continue;
      const auto length = lengths.find(seam.label);
      const double mm = length == lengths.end() ? 0.0 : length->second;
      if (q == p) {
        graph.self_seams[p].push_back({seam.label, 0.5 * mm});  // both sides on this piece
      } else {
        sides[{std::min(p, q), std::max(p, q), seam.label}].push_back(mm);
      }
    }
  }
  std::map<std::pair<int, int>, Neighbour> pairs;
  for (const auto& [key, lengths] : sides) {
    const auto& [p, q, label] = key;
    double mean = 0.0;
    for (double mm : lengths) mean += mm / static_cast<double>(lengths.size());
    Neighbour& pair = pairs[{p, q}];
    pair.length_mm += mean;
    pair.seams.push_back({label, mean});
  }
  for (auto& [key, pair] : pairs) {
    std::sort(pair.seams.begin(), pair.seams.end(), longer_first);
    pair.piece = key.second;
    graph.neighbours[key.first].push_back(pair);
    pair.piece = key.first;
    graph.neighbours[key.second].push_back(pair);
  }
  for (auto& list : graph.neighbours)
    std::sort(list.begin(), list.end(),
              [](const Neighbour& a, const Neighbour& b) { return a.piece < b.piece; });
  for (auto& list : graph.self_seams) std::sort(list.begin(), list.end(), longer_first);
  return graph;
}

// The connected parts of the graph, each in ascending piece order; the larger area first.
std::vector<std::vector<int>> parts_by_area(const PieceGraph& graph) {
  const int n = static_cast<int>(graph.names.size());
  std::vector<int> part(n, -1);
  std::vector<std::vector<int>> parts;
  for (int start = 0; start < n; ++start) {
    if (part[start] >= 0) continue;
    std::vector<int> members = {start};
    part[start] = static_cast<int>(parts.size());
    for (std::size_t i = 0; i < members.size(); ++i)
      for (const Neighbour& next : graph.neighbours[members[i]])
        if (part[next.piece] < 0) {
          part[next.piece] = part[start];
          members.push_back(next.piece);
        }
    std::sort(members.begin(), members.end());
    parts.push_back(std::move(members));
  }
  struct Part {
    double area = 0.0;
    std::vector<int> pieces;
  };
  std::vector<Part> by_area;
  for (std::vector<int>& members : parts) {
    Part part{0.0, std::move(members)};
    for (int p : part.pieces) part.area += graph.areas[p];
    by_area.push_back(std::move(part));
  }
  // Parts were found from their lowest piece up, so a tie keeps the lower numbers first.
  std::stable_sort(by_area.begin(), by_area.end(),
                   [](const Part& a, const Part& b) { return rounded(a.area) > rounded(b.area); });
  std::vector<std::vector<int>> sorted;
  for (Part& part : by_area) sorted.push_back(std::move(part.pieces));
  return sorted;
}

// Pieces crossed from `from` to every other piece of its part, summed (breadth first).
long hops_to_all(const PieceGraph& graph, int from) {
  std::map<int, int> distance = {{from, 0}};
  std::queue<int> queue;
  queue.push(from);
  long sum = 0;
  while (!queue.empty()) {
    const int p = queue.front();
    queue.pop();
    sum += distance[p];
    for (const Neighbour& next : graph.neighbours[p])
      if (distance.emplace(next.piece, distance[p] + 1).second) queue.push(next.piece);
  }
  return sum;
}

int first_piece(const PieceGraph& graph, const std::vector<int>& part, double large_share) {
  double largest = 0.0;
  for (int p : part) largest = std::max(largest, graph.areas[p]);
  int best = -1;
  long best_hops = 0;
  for (int p : part) {  // ascending: a full tie keeps the lower number
    if (graph.areas[p] < large_share * largest) continue;
    const long hops = hops_to_all(graph, p);
    if (best < 0 || hops < best_hops ||
        (hops == best_hops && rounded(graph.areas[p]) > rounded(graph.areas[best]))) {
      best = p;
      best_hops = hops;
    }
  }
  return best;
}

GlueSeam glue(const LabelledSeam& seam, const std::string& partner, bool closes_loop) {
  return {seam.label, partner, seam.length_mm, closes_loop};
}

// The step adding `piece` to the built pieces: to the one it shares the most with, then the
// loops it closes with the others (the larger share first), then those with itself.
BuildStep step_adding(const PieceGraph& graph, int piece, const std::vector<bool>& built) {
  std::vector<const Neighbour*> touching;
  for (const Neighbour& next : graph.neighbours[piece])
    if (built[next.piece]) touching.push_back(&next);
  std::stable_sort(touching.begin(), touching.end(), [](const Neighbour* a, const Neighbour* b) {
    return rounded(a->length_mm) > rounded(b->length_mm);
  });
  BuildStep step;
  step.piece = graph.names[piece];
  for (std::size_t k = 0; k < touching.size(); ++k) {
    const std::string& partner = graph.names[touching[k]->piece];
    if (k == 0) step.attach_to = partner;
    for (const LabelledSeam& seam : touching[k]->seams)
      step.seams.push_back(glue(seam, partner, k > 0));
  }
  for (const LabelledSeam& seam : graph.self_seams[piece])
    step.seams.push_back(glue(seam, step.piece, true));
  return step;
}

// Grows one part from its first piece: each time the unbuilt piece sharing the most seam
// length with the built ones (ties: the lower number).
std::vector<int> growth_order(const PieceGraph& graph, int first) {
  std::map<int, double> shared;  // frontier: unbuilt pieces touching the built ones
  std::vector<bool> built(graph.names.size(), false);
  std::vector<int> order;
  int next = first;
  while (next >= 0) {
    built[next] = true;
    order.push_back(next);
    shared.erase(next);
    for (const Neighbour& n : graph.neighbours[next])
      if (!built[n.piece]) shared[n.piece] += n.length_mm;
    next = -1;
    double best = 0.0;
    for (const auto& [piece, length] : shared)  // ascending piece: ties keep the lower
      if (next < 0 || rounded(length) > rounded(best)) {
        next = piece;
        best = length;
      }
  }
  return order;
}

}  // namespace

const BuildStep* BuildOrder::step_of(const std::string& name) const {
  for (const BuildStep& step : steps)
    if (step.piece == name) return &step;
  return nullptr;
}

bool piece_name_less(const std::string& a, const std::string& b) {
  auto split = [](const std::string& name) {
    std::size_t digits = 0;
    while (digits < name.size() && std::isdigit(static_cast<unsigned char>(name[digits]))) ++digits;
    // Leading zeros do not count; longer digit runs are larger numbers.
    std::size_t zeros = 0;
    while (zeros + 1 < digits && name[zeros] == '0') ++zeros;
    const std::string number = name.substr(zeros, digits - zeros);
    return std::make_tuple(number.size(), number, name.substr(digits));
  };
  return split(a) < split(b);
}

BuildOrder build_order(const PatternLayout& layout, const BuildOrderOptions& options) {
  const PieceGraph graph = piece_graph(layout);
  BuildOrder result;
  std::vector<bool> built(graph.names.size(), false);
  for (const std::vector<int>& part : parts_by_area(graph)) {
    ++result.parts;
    for (int piece : growth_order(graph, first_piece(graph, part, options.large_share))) {
      BuildStep step = step_adding(graph, piece, built);
      step.step = static_cast<int>(result.steps.size()) + 1;
      step.part = result.parts;
      built[piece] = true;
      result.steps.push_back(std::move(step));
    }
  }
  return result;
}

std::string build_step_text(const BuildStep& step) {
  std::string text = std::to_string(step.step) + ": ";
  if (step.attach_to.empty())
    text += (step.part > 1 ? "start part " + std::to_string(step.part) + " with " : "start with ") +
            step.piece;
  else
    text += "glue " + step.piece + " to " + step.attach_to;
  // The seams come grouped by the piece across: the attaching ones, each loop, the piece itself.
  for (std::size_t i = 0; i < step.seams.size(); ++i) {
    const std::string& partner = step.seams[i].partner;
    if (i == 0 || partner != step.seams[i - 1].partner) {
      if (partner == step.piece)
        text += "; close " + step.piece;
      else if (partner != step.attach_to)
        text += "; then to " + partner;
      text += " along ";
    } else {
      text += ", ";
    }
    text += step.seams[i].label;
  }
  return text;
}

}  // namespace papercraft
