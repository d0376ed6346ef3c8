// Printing on the back: a mirror image of each page, texts kept readable.
#include "nodes/layout/print_side.h"

#include <cmath>

#include "core/errors.h"

namespace papercraft {
namespace {

// The angle (clockwise degrees in (-90, 90]) of a label whose reading direction is mirrored:
// the mirrored direction turned upright, so the text still reads left to right.
double mirrored_angle(double degrees) {
  if (degrees == 0.0) return 0.0;
  return -degrees <= -90.0 + 1e-9 ? 180.0 - degrees : -degrees;
}

}  // namespace

void mirror_for_back_printing(PatternLayout& layout) {
  if (layout.print_side == PrintSide::Back)
    throw InvalidInputException("the layout is already mirrored for printing on the back");
  const double width = layout.page.width_mm;
  auto mirror = [width](Vec2& p) { p.x() = width - p.x(); };
  auto mirror_all = [&](std::vector<Vec2>& points) {
    for (Vec2& p : points) mirror(p);
  };
  auto mirror_label = [&](Label& label) {
    mirror(label.position);
    label.angle_degrees = mirrored_angle(label.angle_degrees);
    mirror_all(label.leader);
  };
  for (Page& page : layout.pages)
    for (auto* pieces : {&page.pieces, &page.joints})
      for (PlacedPiece& piece : *pieces) {
        piece.transform.linear.row(0) *= -1.0;
        piece.transform.translation.x() = width - piece.transform.translation.x();
        mirror_all(piece.vertices);
        for (auto& loop : piece.outline) mirror_all(loop);
        for (auto& loop : piece.cut_outline) mirror_all(loop);
        for (PlacedEdge& edge : piece.edges) {
          mirror(edge.a);
          mirror(edge.b);
        }
        for (FoldLine& fold : piece.folds) {
          mirror(fold.a);
          mirror(fold.b);
          fold.kind = fold.kind == FoldKind::Mountain ? FoldKind::Valley : FoldKind::Mountain;
        }
        for (Tab& tab : piece.tabs) {
          for (auto& flap : tab.flaps) mirror_all(flap);
          for (auto& base : tab.bases) mirror_all(base);
          for (TexturePatch& patch : tab.texture) {
            for (Vec2& corner : patch.corners) mirror(corner);
            mirror_all(patch.clip);
          }
        }
        for (auto& mark : piece.marks)
          for (Vec2& end : mark) mirror(end);
        for (Label& label : piece.labels) mirror_label(label);
        mirror_label(piece.number);
      }
  // Every page says which side to print on, the footer's right end where it was.
  const std::string note = " - print on the back";
  for (Page& page : layout.pages) {
    if (page.footer.text.empty()) continue;
    page.footer.text += note;
    page.footer.position.x() -= 0.5 * 0.6 * page.footer.size_mm * static_cast<double>(note.size());
  }
  layout.print_side = PrintSide::Back;
}

}  // namespace papercraft
