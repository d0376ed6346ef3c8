// Rectangle packing: next-fit decreasing height shelves and maximal rectangles, and the
// public pack_rectangles and shelf_pack_page_count.
#include "nodes/layout/rectangle_packing.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <utility>

#include "core/errors.h"
#include "nodes/layout/format_mm.h"
#include "nodes/layout/pages.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {
namespace {

// Rectangles get `spacing` added to both sides and the bin grows by `spacing`, so
// neighbours keep the gap and nothing crosses the real bin.

struct RectItem {
  int index = 0;
  double width = 0.0;  // with spacing
  double height = 0.0;
};

bool fits_bin(double w, double h, double bin_w, double bin_h) {
  return w <= bin_w + kFitSlack && h <= bin_h + kFitSlack;
}

// Next-fit decreasing height: each rectangle lies with its long side along x when that fits.
PackResult shelf_pack(const std::vector<Vec2>& sizes, double bin_w, double bin_h) {
  std::vector<RectItem> items;
  for (int i = 0; i < static_cast<int>(sizes.size()); ++i) {
    double w = std::max(sizes[i].x(), sizes[i].y()), h = std::min(sizes[i].x(), sizes[i].y());
    if (!fits_bin(w, h, bin_w, bin_h)) std::swap(w, h);
    items.push_back({i, w, h});
  }
  std::stable_sort(items.begin(), items.end(),
                   [](const RectItem& a, const RectItem& b) { return a.height > b.height; });
  PackResult result;
  result.placements.resize(sizes.size());
  double x = 0, y = 0, shelf_height = 0;
  for (const RectItem& item : items) {
    if (result.pages == 0) result.pages = 1;
    if (x + item.width > bin_w + kFitSlack) {
      y += shelf_height;
      x = 0;
      shelf_height = 0;
    }
    if (y + item.height > bin_h + kFitSlack) {
      ++result.pages;
      x = y = shelf_height = 0;
    }
    PackedRectangle& placed = result.placements[item.index];
    placed.page = result.pages - 1;
    placed.x = x;
    placed.y = y;
    placed.rotated = (item.width != sizes[item.index].x());
    x += item.width;
    shelf_height = std::max(shelf_height, item.height);
  }
  return result;
}

// Maximal rectangles (Jylanki, "A thousand ways to pack the bin", 2010), one free list per page.
enum class FreeRectChoice { BestShortSideFit, BestAreaFit, TopLeft };

struct FreeRect {
  double x, y, w, h;
};

class MaxRectsPages {
 public:
  MaxRectsPages(double bin_w, double bin_h, FreeRectChoice choice, bool first_page_that_fits)
      : bin_w_(bin_w), bin_h_(bin_h), choice_(choice), first_fit_(first_page_that_fits) {}

  PackedRectangle insert(double w, double h) {
    struct Candidate {
      int page = -1;
      FreeRect rect{};
      bool rotated = false;
      double score1 = std::numeric_limits<double>::infinity(), score2 = score1;
    } best;
    for (int page = 0; page < static_cast<int>(pages_.size()); ++page) {
      for (const FreeRect& free : pages_[page]) {
        for (int turn = 0; turn < 2; ++turn) {
          const double rw = turn ? h : w, rh = turn ? w : h;
          if (rw > free.w + kFitSlack || rh > free.h + kFitSlack) continue;
          double s1 = 0, s2 = 0;
          switch (choice_) {
            case FreeRectChoice::BestShortSideFit:
              s1 = std::min(free.w - rw, free.h - rh);
              s2 = std::max(free.w - rw, free.h - rh);
              break;
            case FreeRectChoice::BestAreaFit:
              s1 = free.w * free.h - rw * rh;
              s2 = std::min(free.w - rw, free.h - rh);
              break;
            case FreeRectChoice::TopLeft:
              s1 = free.y + rh;
              s2 = free.x;
              break;
          }
          if (s1 < best.score1 - 1e-9 || (s1 <= best.score1 + 1e-9 && s2 < best.score2 - 1e-9)) {
            best = {page, {free.x, free.y, rw, rh}, turn == 1, s1, s2};
          }
        }
      }
      if (first_fit_ && best.page >= 0) break;
    }
    if (best.page < 0) {
      pages_.push_back({{0, 0, bin_w_, bin_h_}});
      best.page = static_cast<int>(pages_.size()) - 1;
      const bool turn = !fits_bin(w, h, bin_w_, bin_h_);
      best.rect = {0, 0, turn ? h : w, turn ? w : h};
      best.rotated = turn;
    }
    place(pages_[best.page], best.rect);
    return {best.page, best.rect.x, best.rect.y, best.rotated};
  }

  int page_count() const { return static_cast<int>(pages_.size()); }

 private:
  static void place(std::vector<FreeRect>& free_rects, const FreeRect& used) {
    std::vector<FreeRect> next;
    for (const FreeRect& f : free_rects) {
      const bool overlap = used.x < f.x + f.w && f.x < used.x + used.w && used.y < f.y + f.h &&
                           f.y < used.y + used.h;
      if (!overlap) {
        next.push_back(f);
        continue;
      }
      if (used.x > f.x) next.push_back({f.x, f.y, used.x - f.x, f.h});
      if (used.x + used.w < f.x + f.w)
        next.push_back({used.x + used.w, f.y, f.x + f.w - used.x - used.w, f.h});
      if (used.y > f.y) next.push_back({f.x, f.y, f.w, used.y - f.y});
      if (used.y + used.h < f.y + f.h)
        next.push_back({f.x, used.y + used.h, f.w, f.y + f.h - used.y - used.h});
    }
    auto contains = [](const FreeRect& outer, const FreeRect& inner) {
      return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.w <= outer.x + outer.w &&
             inner.y + inner.h <= outer.y + outer.h;
    };
    std::vector<bool> drop(next.size(), false);
    for (std::size_t i = 0; i < next.size(); ++i) {
      if (next[i].w <= 1e-9 || next[i].h <= 1e-9) drop[i] = true;
      for (std::size_t j = 0; j < next.size() && !drop[i]; ++j) {
        if (i == j || drop[j]) continue;
        if (contains(next[j], next[i])) drop[i] = true;
      }
    }
    free_rects.clear();
    for (std::size_t i = 0; i < next.size(); ++i)
      if (!drop[i]) free_rects.push_back(next[i]);
  }

  double bin_w_, bin_h_;
  FreeRectChoice choice_;
  bool first_fit_;
  std::vector<std::vector<FreeRect>> pages_;
};

PackResult maxrects_pack(const std::vector<Vec2>& sizes, double bin_w, double bin_h) {
  using Key = std::function<double(const Vec2&)>;
  const std::vector<Key> orders = {
      [](const Vec2& s) { return s.x() * s.y(); },
      [](const Vec2& s) { return std::max(s.x(), s.y()); },
      [](const Vec2& s) { return std::min(s.x(), s.y()); },
      [](const Vec2& s) { return s.x() + s.y(); },
  };
  std::optional<PackResult> best;
  for (const Key& key : orders) {
    std::vector<int> order(sizes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return key(sizes[a]) > key(sizes[b]); });
    for (FreeRectChoice choice :
         {FreeRectChoice::BestShortSideFit, FreeRectChoice::BestAreaFit, FreeRectChoice::TopLeft}) {
      for (bool first_fit : {false, true}) {
        MaxRectsPages packer(bin_w, bin_h, choice, first_fit);
        PackResult result;
        result.placements.resize(sizes.size());
        for (int index : order) {
          PackedRectangle placed = packer.insert(sizes[index].x(), sizes[index].y());
          result.placements[index] = placed;
        }
        result.pages = packer.page_count();
        if (!best || result.pages < best->pages) best = std::move(result);
      }
    }
  }
  // The baseline is one more candidate, so MaxRects never needs more pages than Shelf.
  PackResult shelf = shelf_pack(sizes, bin_w, bin_h);
  if (!best || shelf.pages < best->pages) best = std::move(shelf);
  return *best;
}

}  // namespace

PackResult pack_with_spacing(const std::vector<Vec2>& sizes, double bin_width, double bin_height,
                             double spacing, PackingMethod method) {
  if (!(bin_width > 0) || !(bin_height > 0) || !(spacing >= 0))
    throw InvalidInputException("packing bin must have positive size and spacing >= 0");
  std::vector<Vec2> spaced;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const Vec2& s = sizes[i];
    if (!(s.x() > 0) || !(s.y() > 0))
      throw InvalidInputException("rectangle " + std::to_string(i) + " has a non-positive size");
    if (!fits_area(s, bin_width, bin_height))
      throw InvalidInputException("rectangle " + std::to_string(i) + " (" + format_mm(s.x()) +
                                  " x " + format_mm(s.y()) + ") fits no orientation of the " +
                                  format_mm(bin_width) + " x " + format_mm(bin_height) + " bin");
    spaced.push_back(s + Vec2::Constant(spacing));
  }
  const double w = bin_width + spacing, h = bin_height + spacing;
  return method == PackingMethod::Shelf ? shelf_pack(spaced, w, h) : maxrects_pack(spaced, w, h);
}

}  // namespace papercraft::layout_internal

namespace papercraft {

using layout_internal::pack_with_spacing;

std::vector<PackedRectangle> pack_rectangles(const std::vector<Vec2>& sizes, double bin_width,
                                             double bin_height, double spacing,
                                             PackingMethod method) {
  return pack_with_spacing(sizes, bin_width, bin_height, spacing, method).placements;
}

int shelf_pack_page_count(const std::vector<Vec2>& sizes, double bin_width, double bin_height,
                          double spacing) {
  return pack_with_spacing(sizes, bin_width, bin_height, spacing, PackingMethod::Shelf).pages;
}

}  // namespace papercraft
