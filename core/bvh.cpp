#include "core/bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/closest_point.h"
#include "core/errors.h"

namespace papercraft {
namespace {

// Below this depth splits follow the SAH; deeper ones split at the object median, which
// bounds the depth (and so the traversal stack) by about kSahDepth + log2(#F).
constexpr int kSahDepth = 48;
constexpr int kStackSize = 128;
constexpr int kMaxBins = 64;

struct BuildItem {
  Aabb box;
  Vec3 centroid;
  int id;
};

double half_area(const Aabb& box) {
  const Vec3 e = (box.max - box.min).cwiseMax(0.0);
  return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
}

void validate(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) throw InvalidInputException("TriangleBvh: the mesh has no triangles");
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (int v : mesh.triangles[f]) {
      if (v < 0 || v >= vertex_count) {
        throw InvalidInputException(
            "TriangleBvh: triangle " + std::to_string(f) + " refers to vertex " +
            std::to_string(v) + " but the mesh has " + std::to_string(vertex_count) + " vertices");
      }
      if (!mesh.vertices[v].allFinite()) {
        throw InvalidInputException("TriangleBvh: vertex " + std::to_string(v) +
                                    " has a non-finite coordinate");
      }
    }
  }
}

}  // namespace

void Aabb::extend(const Vec3& p) {
  min = min.cwiseMin(p);
  max = max.cwiseMax(p);
}

void Aabb::extend(const Aabb& box) {
  min = min.cwiseMin(box.min);
  max = max.cwiseMax(box.max);
}

double Aabb::squared_distance(const Vec3& p) const {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max({min[k] - p[k], p[k] - max[k], 0.0});
    sum += d * d;
  }
  return sum;
}

namespace {

// The split of items[begin, end) (their centroids bounded by `centroid_box`) along
// `axis` by the surface area heuristic over `bin_count` bins: the items of the bins left of the
// cheapest cut moved before the others, and the position of the first other; -1 where no cut
// leaves items on both sides.
int sah_split(std::vector<BuildItem>& items, int begin, int end, int axis, const Aabb& centroid_box,
              int bin_count) {
  const int count = end - begin;
  const Vec3 extent = centroid_box.max - centroid_box.min;
  struct Bin {
    Aabb box;
    int count = 0;
  };
  std::array<Bin, kMaxBins> bins{};
  const double scale = bin_count / extent[axis];
  auto bin_of = [&](const BuildItem& item) {
    const int b = static_cast<int>((item.centroid[axis] - centroid_box.min[axis]) * scale);
    return std::clamp(b, 0, bin_count - 1);
  };
  for (int i = begin; i < end; ++i) {
    Bin& bin = bins[bin_of(items[i])];
    bin.box.extend(items[i].box);
    ++bin.count;
  }
  std::array<double, kMaxBins> right_cost{};
  Aabb accumulated;
  int accumulated_count = 0;
  for (int b = bin_count - 1; b > 0; --b) {
    accumulated.extend(bins[b].box);
    accumulated_count += bins[b].count;
    right_cost[b] = accumulated_count ? half_area(accumulated) * accumulated_count : 0.0;
  }
  accumulated = Aabb();
  accumulated_count = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  int best_split = -1;
  for (int b = 1; b < bin_count; ++b) {
    accumulated.extend(bins[b - 1].box);
    accumulated_count += bins[b - 1].count;
    if (accumulated_count == 0 || accumulated_count == count) continue;
    const double cost = half_area(accumulated) * accumulated_count + right_cost[b];
    if (cost < best_cost) {
      best_cost = cost;
      best_split = b;
    }
  }
  if (best_split <= 0) return -1;
  BuildItem* split =
      std::partition(items.data() + begin, items.data() + end,
                     [&](const BuildItem& item) { return bin_of(item) < best_split; });
  return static_cast<int>(split - items.data());
}

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh, const TriangleBvhOptions& options)
    : mesh_(mesh) {
  build(options);
}

TriangleBvh::TriangleBvh(TriangleMesh&& mesh, const TriangleBvhOptions& options)
    : mesh_(std::move(mesh)) {
  build(options);
}

void TriangleBvh::build(const TriangleBvhOptions& options) {
  validate(mesh_);
  const int leaf_size = std::max(1, options.leaf_size);
  const int bin_count = std::clamp(options.sah_bins, 2, kMaxBins);
  const int triangle_count = static_cast<int>(mesh_.triangles.size());

  std::vector<BuildItem> items(triangle_count);
  for (int f = 0; f < triangle_count; ++f) {
    BuildItem& item = items[f];
    for (int v : mesh_.triangles[f]) item.box.extend(mesh_.vertices[v]);
    item.centroid = 0.5 * (item.box.min + item.box.max);
    item.id = f;
  }
  struct BuildNode {
    Aabb box;
    int index = 0;  // internal: second child (the first is the next node); leaf: first slot
    int count = 0;  // leaf: number of triangles; internal: 0
  };
  std::vector<BuildNode> build_nodes;
  build_nodes.reserve(2 * static_cast<std::size_t>(triangle_count / leaf_size + 1));
  packed_.reserve(triangle_count);

  struct Task {
    int parent, begin, end, depth;
    bool right;
  };
  // Depth-first order: a left child is created right after its parent; a right child is
  // created when its task is popped, after its sibling's subtree, and linked to its parent.
  std::vector<Task> tasks{{-1, 0, triangle_count, 0, false}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    const int node = static_cast<int>(build_nodes.size());
    build_nodes.emplace_back();
    if (task.right) build_nodes[task.parent].index = node;
    Aabb box, centroid_box;
    for (int i = task.begin; i < task.end; ++i) {
      box.extend(items[i].box);
      centroid_box.extend(items[i].centroid);
    }
    build_nodes[node].box = box;
    const int count = task.end - task.begin;
    int axis = 0;
    const Vec3 extent = centroid_box.max - centroid_box.min;
    extent.maxCoeff(&axis);

    int middle = -1;
    if (count > leaf_size && extent[axis] > 0.0) {
      if (task.depth < kSahDepth && half_area(box) > 0.0)
        middle = sah_split(items, task.begin, task.end, axis, centroid_box, bin_count);
      if (middle <= task.begin || middle >= task.end) {
        middle = task.begin + count / 2;
        std::nth_element(items.begin() + task.begin, items.begin() + middle,
                         items.begin() + task.end, [axis](const BuildItem& x, const BuildItem& y) {
                           return x.centroid[axis] < y.centroid[axis];
                         });
      }
    }

    if (middle < 0) {
      build_nodes[node].index = static_cast<int>(packed_.size());
      build_nodes[node].count = count;
      for (int i = task.begin; i < task.end; ++i) {
        const Triangle& t = mesh_.triangles[items[i].id];
        const Vec3& a = mesh_.vertices[t[0]];
        const Vec3& b = mesh_.vertices[t[1]];
        const Vec3& c = mesh_.vertices[t[2]];
        packed_.push_back({a, b, c, items[i].id, is_regular_triangle(a, b, c)});
      }
      continue;
    }
    tasks.push_back({node, middle, task.end, task.depth + 1, true});
    tasks.push_back({node, task.begin, middle, task.depth + 1, false});
  }

  bounds_ = build_nodes.front().box;
  // Flatten to nodes holding their children's boxes; internal build node i becomes
  // node new_index[i].
  std::vector<int> new_index(build_nodes.size(), -1);
  int internal_count = 0;
  for (std::size_t i = 0; i < build_nodes.size(); ++i) {
    if (build_nodes[i].count == 0) new_index[i] = internal_count++;
  }
  auto set_child = [&](Node& node, int k, int build_child) {
    const BuildNode& child = build_nodes[build_child];
    for (int axis = 0; axis < 3; ++axis) {
      node.min[k][axis] = child.box.min[axis];
      node.max[k][axis] = child.box.max[axis];
    }
    node.child[k] = child.count > 0 ? child.index : new_index[build_child];
    node.count[k] = child.count;
  };
  auto set_empty = [](Node& node, int k) {
    node.min[k].fill(std::numeric_limits<double>::infinity());
    node.max[k].fill(-std::numeric_limits<double>::infinity());
    node.child[k] = -1;
    node.count[k] = 0;
  };
  nodes_.assign(std::max(internal_count, 1), Node{});
  if (internal_count == 0) {
    set_child(nodes_[0], 0, 0);
    set_empty(nodes_[0], 1);
  } else {
    for (std::size_t i = 0; i < build_nodes.size(); ++i) {
      if (build_nodes[i].count > 0) continue;
      Node& node = nodes_[new_index[i]];
      set_child(node, 0, static_cast<int>(i) + 1);
      set_child(node, 1, build_nodes[i].index);
    }
  }
  slot_of_triangle_.assign(triangle_count, -1);
  for (int s = 0; s < static_cast<int>(packed_.size()); ++s) slot_of_triangle_[packed_[s].id] = s;
  // Slot ranges of the internal nodes, children before parents.
  node_slots_.assign(nodes_.size(), {0, -1});
  std::vector<int> pending = {0};
  while (!pending.empty()) {
    const int i = pending.back();
    const Node& n = nodes_[i];
    bool ready = true;
    for (int k = 0; k < 2; ++k) {
      if (n.child[k] >= 0 && n.count[k] == 0 && node_slots_[n.child[k]][1] < 0) {
        pending.push_back(n.child[k]);
        ready = false;
      }
    }
    if (!ready) continue;
    pending.pop_back();
    int first = std::numeric_limits<int>::max(), last = 0;
    for (int k = 0; k < 2; ++k) {
      if (n.child[k] < 0) continue;
      const std::array<int, 2> range =
          n.count[k] > 0 ? std::array<int, 2>{n.child[k], n.count[k]} : node_slots_[n.child[k]];
      if (range[1] == 0) continue;
      first = std::min(first, range[0]);
      last = std::max(last, range[0] + range[1]);
    }
    node_slots_[i] =
        first <= last ? std::array<int, 2>{first, last - first} : std::array<int, 2>{0, 0};
  }
}

BvhSubtree TriangleBvh::root() const {
  return {bounds_, 0, node_slots_[0][0], node_slots_[0][1]};
}

std::array<BvhSubtree, 2> TriangleBvh::children(const BvhSubtree& subtree) const {
  std::array<BvhSubtree, 2> out;
  if (subtree.node < 0) return out;
  const Node& n = nodes_[subtree.node];
  for (int k = 0; k < 2; ++k) {
    if (n.child[k] < 0) continue;
    Aabb box;
    box.min = Vec3(n.min[k][0], n.min[k][1], n.min[k][2]);
    box.max = Vec3(n.max[k][0], n.max[k][1], n.max[k][2]);
    if (n.count[k] > 0) {
      out[k] = {box, -1, n.child[k], n.count[k]};
    } else {
      out[k] = {box, n.child[k], node_slots_[n.child[k]][0], node_slots_[n.child[k]][1]};
    }
  }
  return out;
}

void TriangleBvh::visit_triangle(const Vec3& p, int slot, double& best_squared,
                                 BvhClosestHit& best) const {
  const PackedTriangle& t = packed_[slot];
  const TriangleClosestPoint candidate = t.regular
                                             ? closest_point_on_regular_triangle(p, t.a, t.b, t.c)
                                             : closest_point_on_triangle(p, t.a, t.b, t.c);
  const double d2 = candidate.squared_distance;
  if (d2 < best_squared || (d2 == best_squared && (best.triangle < 0 || t.id < best.triangle))) {
    best_squared = d2;
    best.triangle = t.id;
    best.point = candidate.point;
    best.barycentric = candidate.barycentric;
  }
}

void TriangleBvh::traverse(const Vec3& p, double& best_squared, BvhClosestHit& best) const {
  // Boxes at exactly the best distance are still visited so that ties resolve to the
  // lowest triangle index whatever the visiting order.
  const double px = p.x(), py = p.y(), pz = p.z();
  auto box_distance = [&](const Node& n, int k) {
    const double dx = std::max(std::max(n.min[k][0] - px, px - n.max[k][0]), 0.0);
    const double dy = std::max(std::max(n.min[k][1] - py, py - n.max[k][1]), 0.0);
    const double dz = std::max(std::max(n.min[k][2] - pz, pz - n.max[k][2]), 0.0);
    return dx * dx + dy * dy + dz * dz;
  };
  struct Entry {
    int child, count;
    double distance;
  };
  std::array<Entry, kStackSize> stack;
  int top = 0;
  Entry entry{0, 0, 0.0};
  while (true) {
    if (entry.count > 0) {
      for (int s = entry.child; s < entry.child + entry.count; ++s) {
        visit_triangle(p, s, best_squared, best);
      }
    } else {
      const Node& n = nodes_[entry.child];
      const double distance[2] = {box_distance(n, 0), box_distance(n, 1)};
      const int near = distance[1] < distance[0] ? 1 : 0;
      const int far = 1 - near;
      if (n.child[far] >= 0 && distance[far] <= best_squared) {
        stack[top++] = {n.child[far], n.count[far], distance[far]};
      }
      if (n.child[near] >= 0 && distance[near] <= best_squared) {
        entry = {n.child[near], n.count[near], distance[near]};
        continue;
      }
    }
    while (top > 0 && stack[top - 1].distance > best_squared) --top;
    if (top == 0) return;
    entry = stack[--top];
  }
}

BvhClosestHit TriangleBvh::closest(const Vec3& p, double upper_bound) const {
  BvhClosestHit best;
  double best_squared = upper_bound * upper_bound;
  traverse(p, best_squared, best);
  if (best.found()) best.distance = std::sqrt(best_squared);
  return best;
}

BvhClosestHit TriangleBvh::closest(const Vec3& p, std::span<const int> candidate_triangles) const {
  BvhClosestHit best;
  double best_squared = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < candidate_triangles.size(); ++i) {
    const int t = candidate_triangles[i];
    if (std::find(candidate_triangles.begin(), candidate_triangles.begin() + i, t) !=
        candidate_triangles.begin() + i) {
      continue;
    }
    visit_triangle(p, slot_of_triangle_[t], best_squared, best);
  }
  traverse(p, best_squared, best);
  best.distance = std::sqrt(best_squared);
  return best;
}

std::vector<BvhClosestHit> TriangleBvh::closest(const std::vector<Vec3>& points) const {
  std::vector<BvhClosestHit> hits(points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      int previous = -1;
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        hits[i] = previous >= 0
                                      ? closest(points[i], std::span<const int>(&previous, 1))
                                      : closest(points[i]);
                        previous = hits[i].triangle;
                      }
                    });
  return hits;
}

void TriangleBvh::triangles_meeting(const Aabb& box, std::vector<int>& out) const {
  triangles_meeting(box, out, std::numeric_limits<std::size_t>::max());
}

bool TriangleBvh::triangles_meeting(const Aabb& box, std::vector<int>& out,
                                    std::size_t limit) const {
  const std::size_t start = out.size();
  auto meets = [&](const Node& n, int k) {
    for (int axis = 0; axis < 3; ++axis) {
      if (n.min[k][axis] > box.max[axis] || n.max[k][axis] < box.min[axis]) return false;
    }
    return true;
  };
  auto triangle_meets = [&](const PackedTriangle& t) {
    for (int axis = 0; axis < 3; ++axis) {
      if (std::min({t.a[axis], t.b[axis], t.c[axis]}) > box.max[axis] ||
          std::max({t.a[axis], t.b[axis], t.c[axis]}) < box.min[axis]) {
        return false;
      }
    }
    return true;
  };
  std::array<int, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    for (int k = 0; k < 2; ++k) {
      if (n.child[k] < 0 || !meets(n, k)) continue;
      if (n.count[k] == 0) {
        stack[top++] = n.child[k];
        continue;
      }
      for (int s = n.child[k]; s < n.child[k] + n.count[k]; ++s) {
        if (triangle_meets(packed_[s])) out.push_back(packed_[s].id);
      }
      if (out.size() - start > limit) return false;
    }
  }
  return true;
}

double TriangleBvh::squared_distance_to_triangle(const Vec3& p, int t) const {
  const PackedTriangle& packed = packed_[slot_of_triangle_[t]];
  return packed.regular
             ? closest_point_on_regular_triangle(p, packed.a, packed.b, packed.c).squared_distance
             : closest_point_on_triangle(p, packed.a, packed.b, packed.c).squared_distance;
}

}  // namespace papercraft
