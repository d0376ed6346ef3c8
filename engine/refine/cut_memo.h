#pragma once
// Cuts kept from one refinement for another of the same part. segment.feature refines the
// parts and the model whole (count_strips) to choose between them, and the graph then refines
// the winner again, step by step: the cuts, the costly step, are the same, so the graph takes
// them from here instead of cutting again.

#include <cstdint>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/mesh.h"
#include "engine/refine/decide.h"

namespace papercraft {

struct StripBoundaries;

/// The pieces cut_rejected_piece made of parts, each found again by the part's contents, its
/// strip boundaries and the verdict that rejected it (all compared exactly), so a part whose
/// strip or verdict came out otherwise is cut afresh. Thread-safe. Holds at most
/// `max_faces` faces of pieces (and a copy of each part's points and faces beside them); a cut
/// past that is not kept.
class CutMemo {
 public:
  explicit CutMemo(long max_faces = 2'000'000) : max_faces_(max_faces) {}

  /// Keeps the pieces cut_rejected_piece made of `part`.
  void keep(const Mesh& part, const StripBoundaries& boundaries, const StripVerdict& verdict,
            const std::vector<Mesh>& pieces);

  /// The pieces kept for this part, boundaries and verdict, removed from the memo; nullopt when
  /// none were kept.
  std::optional<std::vector<Mesh>> take(const Mesh& part, const StripBoundaries& boundaries,
                                        const StripVerdict& verdict);

  /// Cuts kept and not yet taken.
  std::size_t size() const;

 private:
  // A part's contents, compared exactly: its points (x, y, z each), its faces' corners and its
  // input vertices.
  struct Part {
    std::vector<double> points;
    std::vector<int> corners;
    std::vector<int> inputs;
  };
  static Part contents_of(const Mesh& part);
  static std::uint64_t key_of(const Part& part, const StripVerdict& verdict);

  struct Entry {
    Part part;
    std::vector<int> first, second;
    Vec3 witness;
    int hole;
    std::vector<Mesh> pieces;
  };
  mutable std::mutex mutex_;
  std::unordered_multimap<std::uint64_t, Entry> entries_;
  long faces_ = 0;
  const long max_faces_;
};

}  // namespace papercraft
