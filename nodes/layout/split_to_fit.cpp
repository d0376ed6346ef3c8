// Splitting a strip that fits no page into pieces that do, cut at inner edges.
#include "nodes/layout/split_to_fit.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <queue>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "core/edge_map.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {
namespace {

// Connected components of a triangle set over shared inner edges.
std::vector<std::vector<int>> components(const StripData& data, const std::vector<int>& set) {
  std::unordered_map<int, int> component;
  for (int t : set) component[t] = -1;
  std::vector<std::vector<int>> result;
  for (int seed : set) {
    if (component[seed] >= 0) continue;
    const int id = static_cast<int>(result.size());
    result.emplace_back();
    std::vector<int> stack{seed};
    component[seed] = id;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      result[id].push_back(t);
      const Triangle& tri = data.strip->triangles[t];
      for (int i = 0; i < 3; ++i) {
        auto it = data.owner.find(directed_edge_key(tri[(i + 1) % 3], tri[i]));
        if (it == data.owner.end()) continue;
        auto c = component.find(it->second);
        if (c != component.end() && c->second < 0) {
          c->second = id;
          stack.push_back(it->second);
        }
      }
    }
    std::sort(result[id].begin(), result[id].end());
  }
  return result;
}

// Triangles of `set` in Dijkstra order (centroid distances over shared edges) from `seed`.
std::vector<int> dijkstra_order(const StripData& data, const std::vector<int>& set, int seed,
                                std::vector<double>* distances = nullptr) {
  const FlatStrip& strip = *data.strip;
  std::unordered_map<int, double> distance;
  for (int t : set) distance[t] = std::numeric_limits<double>::infinity();
  auto centroid = [&](int t) {
    const Triangle& tri = strip.triangles[t];
    return Vec2((data.points[tri[0]] + data.points[tri[1]] + data.points[tri[2]]) / 3.0);
  };
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  distance[seed] = 0;
  queue.push({0, seed});
  std::vector<int> order;
  std::unordered_map<int, char> done;
  while (!queue.empty()) {
    auto [d, t] = queue.top();
    queue.pop();
    if (done.count(t)) continue;
    done[t] = 1;
    order.push_back(t);
    if (distances) distances->push_back(d);
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i) {
      auto it = data.owner.find(directed_edge_key(tri[(i + 1) % 3], tri[i]));
      if (it == data.owner.end()) continue;
      auto n = distance.find(it->second);
      if (n == distance.end() || done.count(it->second)) continue;
      const double nd = d + (centroid(t) - centroid(it->second)).norm();
      if (nd < n->second) {
        n->second = nd;
        queue.push({nd, it->second});
      }
    }
  }
  return order;
}

std::string unique_label(const std::string& wanted, std::set<std::string>& used) {
  std::string label = wanted;
  while (used.count(label)) label += "'";
  used.insert(label);
  return label;
}

// `head` (a connected part of `set`) cut off the rest of `set`: the new seams between head and
// each connected part of the rest labelled <strip id>-<k> in data.split_label; the parts of the
// rest appended to `rest_parts`.
void cut_off(StripData& data, const std::vector<int>& set, std::vector<int> head,
             std::set<std::string>& used_labels, std::vector<std::vector<int>>& rest_parts) {
  std::sort(head.begin(), head.end());
  std::vector<int> rest;
  std::set_difference(set.begin(), set.end(), head.begin(), head.end(), std::back_inserter(rest));
  std::unordered_map<int, char> in_head;
  for (int t : head) in_head[t] = 1;
  for (std::vector<int>& part : components(data, rest)) {
    const std::string label = unique_label(
        std::to_string(data.strip->id) + "-" + std::to_string(++data.splits), used_labels);
    for (int t : part) {
      const Triangle& tri = data.strip->triangles[t];
      for (int i = 0; i < 3; ++i) {
        const int a = tri[i], b = tri[(i + 1) % 3];
        auto it = data.owner.find(directed_edge_key(b, a));
        if (it != data.owner.end() && in_head.count(it->second))
          data.split_label[directed_edge_key(std::min(a, b), std::max(a, b))] = label;
      }
    }
    rest_parts.push_back(std::move(part));
  }
}

// The area of the tightest rectangle round a triangle set (mm^2).
double box_area(const StripData& data, const std::vector<int>& set) {
  bool unused = false;
  return tightest_box(convex_hull(piece_points(data, set)), -1, -1, &unused).size.prod();
}

// A piece of `set` fits width x height in its tightest orientation: one that fits only
// diagonally would take a page to itself.
bool piece_fits(const StripData& data, const std::vector<int>& set, double width, double height) {
  bool unused = false;
  const OrientedBox box = tightest_box(convex_hull(piece_points(data, set)), -1, -1, &unused);
  return fits_area(box.size, width, height);
}

// A divided set (StripData::divided) across the long axis of its tightest rectangle: a straight
// cut where the divided triangles have edges across it, a short zigzag where not. True where it
// cut the set (its parts into `work`, a band that fits into `done`); else `order`, `distance`
// and `clean` (a cut may be made before order[i]) are set for the search of split_to_fit.
bool cut_across_divided(StripData& data, const std::vector<int>& set, double width, double height,
                        std::set<std::string>& used_labels, std::vector<std::vector<int>>& work,
                        std::vector<std::vector<int>>& done, std::vector<int>& order,
                        std::vector<double>& distance, std::vector<char>& clean) {
  auto fits = [&](const std::vector<int>& part) { return piece_fits(data, part, width, height); };
  // Across the long axis of the set's tightest rectangle: a straight cut where the
  // divided triangles have edges across it, a short zigzag where not.
  bool unused = false;
  const OrientedBox box = tightest_box(convex_hull(piece_points(data, set)), -1, -1, &unused);
  // Wider than the page is long: first cut along the long axis into slabs that are not.
  const double longest = std::max(width, height);
  const bool slabs = box.size.y() > longest;
  const Vec2 axis = slabs ? Vec2(-std::sin(box.angle), std::cos(box.angle))
                          : Vec2(std::cos(box.angle), std::sin(box.angle));
  // By the farthest corner along the axis (then the centroid): the two triangles of a
  // grid cell come together, and a cut is made only between triangles whose farthest
  // corners differ, so it runs along the cells' edges, not through their diagonals.
  std::vector<std::tuple<double, double, int>> along;
  double start = std::numeric_limits<double>::infinity();
  for (int t : set) {
    const Triangle& tri = data.strip->triangles[t];
    double farthest = -std::numeric_limits<double>::infinity(), centroid = 0;
    for (int k = 0; k < 3; ++k) {
      farthest = std::max(farthest, axis.dot(data.points[tri[k]]));
      centroid += axis.dot(data.points[tri[k]]) / 3.0;
      start = std::min(start, axis.dot(data.points[tri[k]]));
    }
    along.push_back({farthest, centroid, t});
  }
  std::sort(along.begin(), along.end());
  for (std::size_t i = 0; i < along.size(); ++i) {
    order.push_back(std::get<2>(along[i]));
    distance.push_back(std::get<0>(along[i]) - std::get<0>(along.front()));
    clean.push_back(i == 0 || std::get<0>(along[i]) > std::get<0>(along[i - 1]) + 1e-6);
  }
  if (slabs) {
    // The first of k equal slabs (k as few as keep each within the page's long side),
    // cut at the first clean position past it; it and the rest are split again.
    const double wide = box.size.y();
    const double slab = wide / std::ceil(wide / longest);
    std::size_t cut = 1;
    while (cut < order.size() &&
           !(clean[cut] && std::get<0>(along[cut - 1]) - start >= slab - 1e-6))
      ++cut;
    if (cut < order.size()) {
      std::vector<int> head(order.begin(), order.begin() + cut);
      cut_off(data, set, head, used_labels, work);
      std::sort(head.begin(), head.end());
      for (std::vector<int>& part : components(data, head)) work.push_back(std::move(part));
      return true;
    }
  } else {
    // Straight to the cut: k equal bands, each as long as the page allows for the set's
    // width (its long side where the width fits the short one), the first cut at the clean
    // position nearest 1/k of the length within that; kept where the band fits (a set
    // bent across the axis goes on to the search below).
    const double shortest = std::min(width, height);
    const double allowed = box.size.y() <= shortest ? longest : shortest;
    const double length = box.size.x();
    const double target = length / std::ceil(length / allowed);
    std::size_t best = 0;
    for (std::size_t cut = 1; cut < order.size(); ++cut) {
      if (!clean[cut]) continue;
      const double reach = std::get<0>(along[cut - 1]) - start;
      if (reach > allowed) break;
      if (best == 0 ||
          std::abs(reach - target) < std::abs(std::get<0>(along[best - 1]) - start - target))
        best = cut;
    }
    if (best > 0) {
      std::vector<int> head(order.begin(), order.begin() + best);
      std::sort(head.begin(), head.end());
      auto parts = components(data, head);
      if (parts.size() == 1 && fits(head)) {
        cut_off(data, set, head, used_labels, work);
        done.push_back(std::move(head));
        return true;
      }
    }
  }
  return false;
}

}  // namespace

std::vector<std::vector<int>> split_to_fit(StripData& data, double width, double height,
                                           std::set<std::string>& used_labels) {
  return split_to_fit(data, data.triangles, width, height, used_labels);
}

// Splits the set into connected triangle sets each fitting width x height: a Dijkstra
// prefix from one end of the set (a ruled strip is a path of triangles, so the cut is one
// ruling), repeated on what is left. The prefix is not the largest that fits (that leaves
// a sliver at the end) but the one nearest 1/k of the set's length, where k is the number
// of pieces the greedy split needs, among those that leave a rest still splittable into
// k - 1 pieces: the pieces come out of similar length.
std::vector<std::vector<int>> split_to_fit(StripData& data, const std::vector<int>& triangles,
                                           double width, double height,
                                           std::set<std::string>& used_labels) {
  std::vector<std::vector<int>> done;
  std::vector<std::vector<int>> work = components(data, triangles);
  auto fits = [&](const std::vector<int>& part) { return piece_fits(data, part, width, height); };
  while (!work.empty()) {
    std::vector<int> set = std::move(work.front());
    work.erase(work.begin());
    if (set.size() <= 1 || fits(set)) {
      done.push_back(std::move(set));
      continue;
    }
    std::vector<double> distance;
    std::vector<int> order;
    std::vector<char> clean;  // divided: a cut may be made before order[i]
    if (data.divided) {
      if (cut_across_divided(data, set, width, height, used_labels, work, done, order, distance,
                             clean))
        continue;
    } else {
      std::vector<int> from_first = dijkstra_order(data, set, set.front());
      order = dijkstra_order(data, set, from_first.back(), &distance);
    }
    // The longest prefix of order[begin..] that fits (at least one triangle).
    auto longest_fitting = [&](std::size_t begin) {
      std::size_t lo = begin + 1, hi = order.size();
      while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (fits(std::vector<int>(order.begin() + begin, order.begin() + mid)))
          lo = mid;
        else
          hi = mid - 1;
      }
      return lo;
    };
    auto greedy_count = [&](std::size_t begin) {
      int count = 0;
      for (; begin < order.size(); ++count) begin = longest_fitting(begin);
      return count;
    };
    std::size_t lo = std::min(longest_fitting(0), order.size() - 1);
    const int pieces = greedy_count(0);
    if (pieces >= 2 && lo > 1) {
      // Smallest cut whose rest still splits into pieces - 1 (the count only falls as the
      // cut moves on), then the cut nearest 1/pieces of the length within [first, lo].
      std::size_t first = 1, last = lo;
      while (first < last) {
        const std::size_t mid = (first + last) / 2;
        if (greedy_count(mid) <= pieces - 1)
          last = mid;
        else
          first = mid + 1;
      }
      const double target = distance.back() / pieces;
      std::size_t cut =
          std::lower_bound(distance.begin(), distance.end(), target) - distance.begin();
      cut = std::clamp(cut, first, lo);
      if (cut < lo && fits(std::vector<int>(order.begin(), order.begin() + cut)) &&
          components(data, std::vector<int>(order.begin() + cut, order.end())).size() == 1)
        lo = cut;
    }
    if (data.divided) {
      std::size_t at = lo;
      while (at > 1 && !clean[at]) --at;
      if (clean[at]) lo = at;
    }
    std::vector<int> head(order.begin(), order.begin() + lo);
    if (data.divided) {
      // A cut across a bent set may leave its head in parts: the part at its start is cut off.
      for (std::vector<int>& part : components(data, head))
        if (std::binary_search(part.begin(), part.end(), order.front())) {
          head = std::move(part);
          break;
        }
    }
    cut_off(data, set, head, used_labels, work);
    std::sort(head.begin(), head.end());
    done.push_back(std::move(head));
  }
  return done;
}

// Splits the strip where it bends. Along a Dijkstra order from one end of each connected set
// (a ruled strip is a path of triangles, so a cut is one ruling), cuts are chosen among
// kSteps + 1 evenly spaced positions, parts at least kShortest steps long: the choice
// (by dynamic programming) minimises the area of the tightest rectangles round the parts plus
// kPerPiece times the set's own area for each part after the first, so a cut is made only
// where it saves much paper round the parts.
std::vector<std::vector<int>> split_at_bends(StripData& data, std::set<std::string>& used_labels) {
  constexpr int kSteps = 24, kShortest = 2;
  constexpr double kPerPiece = 0.5, kShortestMm = 20.0;
  std::vector<std::vector<int>> done;
  for (std::vector<int>& set : components(data, data.triangles)) {
    const std::vector<int> from_first = dijkstra_order(data, set, set.front());
    std::vector<double> distance;
    const std::vector<int> order = dijkstra_order(data, set, from_first.back(), &distance);
    const double total = distance.back();
    if (set.size() < 4 || total < kShortest * kShortestMm) {
      done.push_back(std::move(set));
      continue;
    }
    // Cut positions in the order: position k at k/kSteps of the length (0 and the end).
    std::vector<std::size_t> at(kSteps + 1);
    for (int k = 0; k <= kSteps; ++k)
      at[k] =
          std::lower_bound(distance.begin(), distance.end(), total * k / kSteps) - distance.begin();
    at[0] = 0;
    at[kSteps] = order.size();
    double area = 0.0;
    for (int t : set) {
      const Triangle& tri = data.strip->triangles[t];
      area += 0.5 * std::abs(cross(data.points[tri[1]] - data.points[tri[0]],
                                   data.points[tri[2]] - data.points[tri[0]]));
    }
    // The part from position i to j: the tightest rectangle's area, or infinity where it is
    // empty or not connected.
    auto part_cost = [&](int i, int j) {
      if (at[j] <= at[i]) return std::numeric_limits<double>::infinity();
      std::vector<int> part(order.begin() + at[i], order.begin() + at[j]);
      std::sort(part.begin(), part.end());
      if (i > 0 && components(data, part).size() != 1)
        return std::numeric_limits<double>::infinity();
      return box_area(data, part);
    };
    // best[j]: the least cost of the order up to position j; from[j] the last cut before it.
    std::vector<double> best(kSteps + 1, std::numeric_limits<double>::infinity());
    std::vector<int> from(kSteps + 1, -1);
    best[0] = 0.0;
    for (int j = kShortest; j <= kSteps; ++j)
      for (int i = 0; i + kShortest <= j; ++i) {
        if (i > 0 && i < kShortest) continue;
        if (j < kSteps && kSteps - j < kShortest) continue;
        if (!std::isfinite(best[i])) continue;
        const double cost = best[i] + part_cost(i, j) + (i > 0 ? kPerPiece * area : 0.0);
        if (cost < best[j]) {
          best[j] = cost;
          from[j] = i;
        }
      }
    std::vector<int> cuts;
    for (int j = from[kSteps]; j > 0; j = from[j]) cuts.push_back(j);
    if (cuts.empty()) {
      done.push_back(std::move(set));
      continue;
    }
    // Cut off from the far end back: each head is a prefix of the order, so the rest stays
    // one connected part with the parts cut off before it.
    std::vector<int> rest = set;
    for (int cut : cuts) {
      std::vector<int> head(order.begin(), order.begin() + at[cut]);
      std::vector<std::vector<int>> tail;
      cut_off(data, rest, head, used_labels, tail);
      for (auto& part : tail) done.push_back(std::move(part));
      std::sort(head.begin(), head.end());
      rest = std::move(head);
    }
    done.push_back(std::move(rest));
  }
  return done;
}

}  // namespace papercraft::layout_internal
