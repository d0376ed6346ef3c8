#include "engine/refine/cut_memo.h"

#include <cstring>

#include "engine/refine/refine.h"

namespace papercraft {

namespace {

// FNV-1a over the bytes of the part's points, faces and input vertices and of the verdict's
// witness: two copies of one surface in a model are two parts.
std::uint64_t key_of(const Mesh& part, const StripVerdict& verdict) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  };
  const std::size_t counts[2] = {part.n_vertices(), part.n_faces()};
  mix(counts, sizeof counts);
  for (auto v : part.vertices()) mix(part.point(v).data(), 3 * sizeof(double));
  for (auto f : part.faces()) {
    for (auto v : part.fv_range(f)) {
      const int index = v.idx();
      mix(&index, sizeof index);
    }
  }
  OpenMesh::VPropHandleT<int> input_vertex;
  if (part.get_property_handle(input_vertex, kInputVertexProperty)) {
    for (auto v : part.vertices()) mix(&part.property(input_vertex, v), sizeof(int));
  }
  mix(verdict.witness.data(), 3 * sizeof(double));
  mix(&verdict.hole, sizeof verdict.hole);
  return h;
}

}  // namespace

void CutMemo::keep(const Mesh& part, const StripBoundaries& boundaries, const StripVerdict& verdict,
                   const std::vector<Mesh>& pieces) {
  long faces = 0;
  for (const Mesh& piece : pieces) faces += static_cast<long>(piece.n_faces());
  const std::uint64_t key = key_of(part, verdict);
  std::lock_guard lock(mutex_);
  if (faces_ + faces > max_faces_) return;
  faces_ += faces;
  entries_.emplace(
      key, Entry{key, boundaries.first, boundaries.second, verdict.witness, verdict.hole, pieces});
}

std::optional<std::vector<Mesh>> CutMemo::take(const Mesh& part, const StripBoundaries& boundaries,
                                               const StripVerdict& verdict) {
  const std::uint64_t key = key_of(part, verdict);
  std::lock_guard lock(mutex_);
  const auto [from, to] = entries_.equal_range(key);
  for (auto it = from; it != to; ++it) {
    const Entry& entry = it->second;
    if (entry.first != boundaries.first || entry.second != boundaries.second ||
        entry.witness != verdict.witness || entry.hole != verdict.hole)
      continue;
    std::vector<Mesh> pieces = std::move(it->second.pieces);
    for (const Mesh& piece : pieces) faces_ -= static_cast<long>(piece.n_faces());
    entries_.erase(it);
    return pieces;
  }
  return std::nullopt;
}

std::size_t CutMemo::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace papercraft
