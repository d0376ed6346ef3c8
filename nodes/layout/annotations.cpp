// Seam labels, piece numbers, fold lines and alignment marks on the pieces, and label_box.
#include "nodes/layout/annotations.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <utility>

#include "core/edge_map.h"
#include "nodes/layout/label_placement.h"
#include "nodes/layout/pages.h"
#include "nodes/layout/piece_shapes.h"

namespace papercraft::layout_internal {
namespace {

// Where the piece number goes: the incentre of a triangle with (nearly) the largest
// inscribed circle, the one nearest the piece's centroid; and that circle's radius.
std::pair<Vec2, double> number_spot(const StripData& data, const Piece& piece) {
  struct Candidate {
    Vec2 centre;
    double radius;
  };
  std::vector<Candidate> candidates;
  Vec2 centroid = Vec2::Zero();
  double area = 0, largest = 0;
  for (int t : piece.triangles) {
    const auto circle = incircle(data, t);
    if (!circle) continue;
    const Triangle& tri = data.strip->triangles[t];
    const Vec2 &a = data.points[tri[0]], &b = data.points[tri[1]], &c = data.points[tri[2]];
    const double twice_area = std::abs(cross(b - a, c - a));
    centroid += twice_area * (a + b + c) / 3.0;
    area += twice_area;
    candidates.push_back({circle->first, circle->second});
    largest = std::max(largest, circle->second);
  }
  if (candidates.empty()) return {data.points[data.strip->triangles[piece.triangles[0]][0]], 0};
  if (area > 0) centroid /= area;
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates)
    if (c.radius >= 0.8 * largest &&
        (!best || (c.centre - centroid).norm() < (best->centre - centroid).norm()))
      best = &c;
  return {best->centre, best->radius};
}

}  // namespace

void add_alignment_marks(const StripData& data, Piece& piece, const Chain& chain, double length) {
  if (chain.closed || length <= 0.0) return;
  const auto& loop = piece.loops[chain.loop];
  const int n = static_cast<int>(loop.size());
  auto tick = [&](int vertex, int edge) {
    const Vec2 d = data.points[loop[edge].v1] - data.points[loop[edge].v0];
    if (d.norm() == 0.0) return;
    const Vec2 across = Vec2(-d.y(), d.x()).normalized() * (0.5 * length);
    const Vec2& at = data.points[vertex];
    piece.marks.push_back({at - across, at + across});
  };
  const int first = chain.start, last = (chain.start + chain.count - 1) % n;
  if (loop[(first + n - 1) % n].kind == EdgeKind::Seam) tick(loop[first].v0, first);
  if (loop[(last + 1) % n].kind == EdgeKind::Seam) tick(loop[last].v1, last);
}

PieceLabel chain_label(const StripData& data, const Piece& piece, const Chain& chain,
                       const std::string& text, double size) {
  const auto& loop = piece.loops[chain.loop];
  const double total = chain_length(data, piece, chain);
  const double text_width = 0.6 * static_cast<double>(text.size());
  size = std::max(std::min(size, (total - 0.5) / std::max(text_width, 1e-9)), std::min(size, 2.0));
  // The edge at the chain's middle (a closed chain has none: its longest edge), with the
  // text kept clear of the edge's corners where the edge is long enough.
  int chosen = 0;
  double at = 0.5;
  double walked = 0, longest = -1;
  for (int i = 0; i < chain.count; ++i) {
    const PieceEdge& e = loop[(chain.start + i) % loop.size()];
    const double length = (data.points[e.v1] - data.points[e.v0]).norm();
    if (chain.closed) {
      if (length > longest) {
        longest = length;
        chosen = i;
      }
    } else if (walked + length >= 0.5 * total || i == chain.count - 1) {
      chosen = i;
      at = length > 0 ? std::clamp((0.5 * total - walked) / length, 0.0, 1.0) : 0.5;
      break;
    }
    walked += length;
  }
  const PieceEdge& e = loop[(chain.start + chosen) % loop.size()];
  const Vec2 a = data.points[e.v0], b = data.points[e.v1];
  const double length = (b - a).norm();
  const double clearance = 0.5 * text_width * size + 0.5;
  if (length > 2 * clearance)
    at = std::clamp(at, clearance / length, 1.0 - clearance / length);
  else
    at = 0.5;
  const Vec2 d = length > 0 ? Vec2((b - a) / length) : Vec2::UnitX();
  return {text, a + at * (b - a) + Vec2(-d.y(), d.x()) * (0.6 * size + 0.6), d, size, -1, false,
          {}};
}

std::vector<FoldLine> piece_folds(const StripData& data, const Piece& piece,
                                  double threshold_degrees, double strong_degrees) {
  const FlatStrip& strip = *data.strip;
  std::unordered_map<int, char> in_piece;
  for (int t : piece.triangles) in_piece[t] = 1;
  std::vector<FoldLine> folds;  // in the strip frame; placed later
  for (int t : piece.triangles) {
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = tri[i], b = tri[(i + 1) % 3], c = tri[(i + 2) % 3];
      if (a > b) continue;
      auto it = data.owner.find(directed_edge_key(b, a));
      if (it == data.owner.end() || !in_piece.count(it->second)) continue;
      const Triangle& other = strip.triangles[it->second];
      int d = -1;
      for (int k = 0; k < 3; ++k)
        if (other[k] != a && other[k] != b) d = other[k];
      const Vec3 &pa = strip.vertices3d[a], &pb = strip.vertices3d[b];
      const Vec3 n1 = (pb - pa).cross(strip.vertices3d[c] - pa);
      const Vec3 n2 = (pa - pb).cross(strip.vertices3d[d] - pb);
      if (n1.norm() == 0 || n2.norm() == 0) continue;
      const double bend =
          std::acos(std::clamp(n1.normalized().dot(n2.normalized()), -1.0, 1.0)) / kDegree;
      if (bend <= threshold_degrees) continue;
      const bool convex = (strip.vertices3d[d] - pa).dot(n1) < 0;
      folds.push_back({data.points[a], data.points[b],
                       convex ? FoldKind::Mountain : FoldKind::Valley, bend,
                       bend < strong_degrees});
    }
  }
  return folds;
}

PieceLabel piece_number(const StripData& data, const Piece& piece, const OrientedBox& box,
                        const LayoutOptions& options) {
  auto [centre, radius] = number_spot(data, piece);
  PieceLabel number;
  number.text = piece.name;
  number.position = centre;
  number.size =
      std::min(options.number_size_mm,
               std::max(std::min(options.min_text_mm, options.number_size_mm), 1.8 * radius));
  number.direction = Vec2(std::cos(box.angle), std::sin(box.angle));
  return number;
}

std::vector<std::array<Vec2, 4>> leader_boxes(const std::vector<Vec2>& leader) {
  std::vector<std::array<Vec2, 4>> boxes;
  for (std::size_t i = 0; i + 1 < leader.size(); ++i)
    boxes.push_back(leader_box({leader[i], leader[i + 1]}));
  return boxes;
}

std::array<Vec2, 4> leader_box(const std::vector<Vec2>& leader) {
  const Vec2 d = leader.back() - leader.front();
  const double length = d.norm();
  const Vec2 n = length > 0 ? Vec2(Vec2(-d.y(), d.x()) * (kLeaderHalfWidth / length))
                            : Vec2(kLeaderHalfWidth, 0.0);
  return {leader.front() - n, leader.back() - n, leader.back() + n, leader.front() + n};
}

namespace {

// Everything arrange_labels reads of a piece, its strip and its chains, byte for byte.
std::string label_key(const StripData& data, const Piece& piece, const std::vector<Chain>& chains,
                      const OrientedBox& box) {
  std::string key;
  auto put = [&key](const auto& value) {
    key.append(reinterpret_cast<const char*>(&value), sizeof(value));
  };
  auto put_text = [&](const std::string& text) {
    put(text.size());
    key += text;
  };
  auto put_points = [&](const std::vector<Vec2>& points) {
    put(points.size());
    for (const Vec2& q : points) put(q.x()), put(q.y());
  };
  put(box.angle), put(box.min.x()), put(box.min.y()), put(box.size.x()), put(box.size.y());
  // The name by its length only: a split before this piece renumbers it, and its number
  // takes the same room at the same length.
  put(piece.strip), put(piece.joint), put(piece.name.size());
  put(piece.triangles.size());
  for (int t : piece.triangles) {
    put(t);
    for (int v : data.strip->triangles[t]) put(data.points[v].x()), put(data.points[v].y());
  }
  put(piece.loops.size());
  for (const auto& loop : piece.loops) {
    put(loop.size());
    for (const PieceEdge& e : loop) {
      put(e.v0), put(e.v1), put(e.kind), put(e.flap), put(e.flap_first);
      put(e.edge_flaps.size());
      for (int f : e.edge_flaps) put(f);
      put_text(e.label);
      put_text(e.printed);
    }
  }
  put(piece.flaps.size());
  for (const Flap& flap : piece.flaps) {
    put_points(flap.base);
    put_points(flap.outer);
    put(flap.tab);
  }
  put(piece.tabs.size());
  for (const PieceTab& tab : piece.tabs) {
    put_text(tab.label);
    put(tab.flaps.size());
    for (int f : tab.flaps) put(f);
  }
  put(piece.labels.size());
  for (const PieceLabel& label : piece.labels) {
    put_text(label.text);
    put(label.position.x()), put(label.position.y()), put(label.direction.x());
    put(label.direction.y()), put(label.size), put(label.chain >= 0), put(label.outside);
    put_points(label.leader);
    if (label.chain < 0) continue;
    const Chain& chain = chains[label.chain];
    put(chain.loop), put(chain.start), put(chain.count), put(chain.closed);
  }
  return key;
}

}  // namespace

void arrange_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                    const OrientedBox& box, const LayoutOptions& options,
                    std::vector<std::string>& warnings, LabelCache* cache) {
  std::string key;
  if (cache) {
    key = label_key(data, piece, chains, box);
    if (const auto found = cache->entries.find(key); found != cache->entries.end()) {
      const LabelCache::Entry& entry = found->second;
      // The chains by their index in this layout's list (the same chains, numbered anew
      // where pieces before were split).
      std::vector<PieceLabel> labels = entry.labels;
      for (std::size_t k = 0; k < labels.size(); ++k)
        labels[k].chain = piece.labels[entry.kept[k]].chain;
      piece.labels = std::move(labels);
      piece.number = entry.number;
      if (piece.number) piece.number->text = piece.name;
      // The notes name the piece as it was named then.
      const std::string then = "piece " + entry.name + ":", now = "piece " + piece.name + ":";
      for (const std::string& note : entry.warnings)
        warnings.push_back(note.rfind(then, 0) == 0 ? now + note.substr(then.size()) : note);
      return;
    }
  }
  const Piece before = piece;
  std::vector<std::string> notes;
  Placement best = place_labels(data, piece, chains, box, options, false, notes);
  std::vector<std::size_t> kept = best.kept;  // positions in before.labels of those kept
  // Labels that found no clear spot take the spots first in another pass, the others fill in
  // around them; a crowded corner often has room for all where the order was the trouble. Up
  // to three more passes, each putting the labels crowded in any pass before first; then one
  // with the number placed after the labels (it has more places to go than a label). The pass
  // with the fewest labels and numbers left without a clear spot is kept (the first on a tie).
  std::vector<std::size_t> first;  // positions in before.labels, crowded in some pass
  std::vector<std::size_t> order(before.labels.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  Placement last = best;  // the pass before, in `order`
  for (int pass = 0; pass < 4 && best.misses() > 0; ++pass) {
    const bool number_last = pass == 3;
    for (std::size_t m : last.crowded)
      if (std::find(first.begin(), first.end(), order[m]) == first.end()) first.push_back(order[m]);
    std::vector<std::size_t> next = first;
    for (std::size_t n = 0; n < before.labels.size(); ++n)
      if (std::find(first.begin(), first.end(), n) == first.end()) next.push_back(n);
    Piece retry = before;
    for (std::size_t k = 0; k < next.size(); ++k) retry.labels[k] = before.labels[next[k]];
    std::vector<std::string> retry_notes;
    last = place_labels(data, retry, chains, box, options, number_last, retry_notes);
    order = std::move(next);
    if (last.misses() >= best.misses()) continue;
    // Back in the labels' own order.
    std::vector<std::pair<std::size_t, PieceLabel>> sorted;
    for (std::size_t k = 0; k < last.kept.size(); ++k)
      sorted.emplace_back(order[last.kept[k]], std::move(retry.labels[k]));
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    retry.labels.clear();
    kept.clear();
    for (auto& [n, label] : sorted) {
      retry.labels.push_back(std::move(label));
      kept.push_back(n);
    }
    best = last;
    piece = std::move(retry);
    notes = std::move(retry_notes);
  }
  warnings.insert(warnings.end(), notes.begin(), notes.end());
  if (cache)
    cache->entries[std::move(key)] = {piece.name, piece.labels, std::move(kept), piece.number,
                                      std::move(notes)};
}

std::vector<std::array<Vec2, 4>> text_boxes(const Piece& piece) {
  std::vector<std::array<Vec2, 4>> boxes;
  if (piece.number)
    boxes.push_back(text_box(piece.number->position, piece.number->direction, piece.number->size,
                             piece.number->text.size()));
  for (const PieceLabel& label : piece.labels)
    boxes.push_back(text_box(label.position, label.direction, label.size, label.text.size()));
  return boxes;
}

std::vector<FoldLine> clear_of_text(const std::vector<FoldLine>& folds,
                                    const std::vector<std::array<Vec2, 4>>& boxes) {
  std::vector<FoldLine> out;
  for (const FoldLine& fold : folds) {
    std::vector<std::array<Vec2, 2>> parts{{fold.a, fold.b}};
    for (const auto& box : boxes) {
      std::vector<std::array<Vec2, 2>> next;
      for (const auto& part : parts)
        for (const auto& piece : segment_outside(part[0], part[1], box)) next.push_back(piece);
      parts = std::move(next);
    }
    for (const auto& part : parts) {
      if ((part[1] - part[0]).norm() < 1e-6) continue;
      FoldLine shortened = fold;
      shortened.a = part[0];
      shortened.b = part[1];
      out.push_back(shortened);
    }
  }
  return out;
}

}  // namespace papercraft::layout_internal

namespace papercraft {

using layout_internal::kDegree;
using layout_internal::text_box;

std::array<Vec2, 4> label_box(const Label& label) {
  const double angle = label.angle_degrees * kDegree;
  return text_box(label.position, Vec2(std::cos(angle), std::sin(angle)), label.size_mm,
                  label.text.size());
}

}  // namespace papercraft
