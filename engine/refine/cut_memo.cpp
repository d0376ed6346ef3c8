#include "engine/refine/cut_memo.h"


#include "engine/refine/refine.h"

namespace papercraft {

namespace {

std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  return h;
}

}  // namespace

CutMemo::Part CutMemo::contents_of(const Mesh& part) {
  Part contents;
  contents.points.reserve(3 * part.n_vertices());
  for (auto v : part.vertices())
    contents.points.insert(contents.points.end(), part.point(v).data(), part.point(v).data() + 3);
  contents.corners.reserve(3 * part.n_faces());
  for (auto f : part.faces())
    for (auto v : part.fv_range(f)) contents.corners.push_back(v.idx());
  OpenMesh::VPropHandleT<int> input_vertex;
  if (part.get_property_handle(input_vertex, kInputVertexProperty))
    for (auto v : part.vertices()) contents.inputs.push_back(part.property(input_vertex, v));
  return contents;
}

// FNV-1a over the part's points, faces and input vertices and the verdict's witness and hole:
// two copies of one surface in a model are two parts.
std::uint64_t CutMemo::key_of(const Part& part, const StripVerdict& verdict) {
  std::uint64_t h = 1469598103934665603ull;
  const std::size_t counts[3] = {part.points.size(), part.corners.size(), part.inputs.size()};
  h = fnv1a(h, counts, sizeof counts);
  h = fnv1a(h, part.points.data(), part.points.size() * sizeof(double));
  h = fnv1a(h, part.corners.data(), part.corners.size() * sizeof(int));
  h = fnv1a(h, part.inputs.data(), part.inputs.size() * sizeof(int));
  h = fnv1a(h, verdict.witness.data(), 3 * sizeof(double));
  return fnv1a(h, &verdict.hole, sizeof verdict.hole);
}

void CutMemo::keep(const Mesh& part, const StripBoundaries& boundaries, const StripVerdict& verdict,
                   const std::vector<Mesh>& pieces) {
  long faces = 0;
  for (const Mesh& piece : pieces) faces += static_cast<long>(piece.n_faces());
  Part contents = contents_of(part);
  const std::uint64_t key = key_of(contents, verdict);
  std::lock_guard lock(mutex_);
  if (faces_ + faces > max_faces_) return;
  faces_ += faces;
  entries_.emplace(key, Entry{std::move(contents), boundaries.first, boundaries.second,
                              verdict.witness, verdict.hole, pieces});
}

std::optional<std::vector<Mesh>> CutMemo::take(const Mesh& part, const StripBoundaries& boundaries,
                                               const StripVerdict& verdict) {
  const Part contents = contents_of(part);
  const std::uint64_t key = key_of(contents, verdict);
  std::lock_guard lock(mutex_);
  const auto [from, to] = entries_.equal_range(key);
  for (auto it = from; it != to; ++it) {
    const Entry& entry = it->second;
    if (entry.part.points != contents.points || entry.part.corners != contents.corners ||
        entry.part.inputs != contents.inputs || entry.first != boundaries.first || entry.second != boundaries.second ||
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
