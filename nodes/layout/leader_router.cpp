// LeaderRouter: cut lines in buckets for clearance tests, and leaders that bend.
#include "nodes/layout/leader_router.h"

namespace papercraft::layout_internal {

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

bool inside_convex(const Vec2& q, const std::array<Vec2, 4>& box) {
  bool positive = false, negative = false;
  for (int i = 0; i < 4; ++i) {
    const double side = cross(box[(i + 1) % 4] - box[i], q - box[i]);
    positive = positive || side > 0;
    negative = negative || side < 0;
  }
  return !(positive && negative);
}

LeaderRouter::LeaderRouter(const std::vector<std::array<Vec2, 2>>& lines, double step)
    : lines_(lines), step_(step) {
  for (const auto& line : lines) bounds_.add(line[0]), bounds_.add(line[1]);
  if (lines.empty()) return;
  bucket_ = std::max(4.0, (bounds_.hi - bounds_.lo).maxCoeff() / 256.0);
  bounds_.lo -= Vec2::Constant(bucket_);
  columns_ = static_cast<int>((bounds_.hi.x() - bounds_.lo.x()) / bucket_) + 2;
  rows_ = static_cast<int>((bounds_.hi.y() - bounds_.lo.y()) / bucket_) + 2;
  buckets_.resize(static_cast<std::size_t>(columns_) * rows_);
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    const auto [c0, r0] = cell(lines[i][0].cwiseMin(lines[i][1]));
    const auto [c1, r1] = cell(lines[i][0].cwiseMax(lines[i][1]));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        buckets_[static_cast<std::size_t>(r) * columns_ + c].push_back(i);
  }
}

bool LeaderRouter::clear(const Vec2& a, const Vec2& b,
                         const std::vector<std::array<Vec2, 4>>& taken) const {
  if (!buckets_.empty()) {
    const auto [c0, r0] = cell(a.cwiseMin(b));
    const auto [c1, r1] = cell(a.cwiseMax(b));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        for (int i : buckets_[static_cast<std::size_t>(r) * columns_ + c])
          if (segments_cross(a, b, lines_[i][0], lines_[i][1])) return false;
  }
  for (const auto& box : taken)
    if (segment_crosses(a, b, box)) return false;
  return true;
}

bool LeaderRouter::box_clear(const std::array<Vec2, 4>& box) const {
  if (buckets_.empty()) return true;
  Vec2 lo = box[0], hi = box[0];
  for (const Vec2& q : box) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  const auto [c0, r0] = cell(lo);
  const auto [c1, r1] = cell(hi);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c)
      for (int i : buckets_[static_cast<std::size_t>(r) * columns_ + c])
        if (segment_crosses(lines_[i][0], lines_[i][1], box)) return false;
  return true;
}

}  // namespace papercraft::layout_internal
