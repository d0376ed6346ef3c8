#pragma once
// The printed pattern as pure geometry in page millimetres: what `layout` produces and
// `export` draws (SVG, PDF). See nodes/layout/pages.h for how a layout is made and the
// conventions (page coordinates, printed side, folds, tabs).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/page_size.h"
#include "core/strip.h"

namespace papercraft {

/// Text to draw: centred on `position` (page mm), `angle_degrees` clockwise on the page
/// from left-to-right (the SVG rotate() sense), always in (-90, 90] so it reads upright.
struct Label {
  std::string text;
  Vec2 position = Vec2::Zero();
  double angle_degrees = 0.0;
  double size_mm = 2.5;
  /// Printed beside its piece, on the paper around it (no room on the piece).
  bool outside = false;
  /// For a label printed away from its seam: a thin line from the seam (first point, page
  /// mm) to the text. Empty: none.
  std::vector<Vec2> leader;
};

enum class FoldKind { Mountain, Valley };

/// The side of the sheet the pattern is printed on. Front: the printed side is the outside of
/// the model. Back: every page is mirrored (x -> page width - x) so that, printed and cut from
/// the back of the sheet, the pieces come out the right way round with the print inside.
enum class PrintSide { Front, Back };

struct FoldLine {
  Vec2 a = Vec2::Zero();
  Vec2 b = Vec2::Zero();
  FoldKind kind = FoldKind::Mountain;
  double bend_degrees = 0.0;  // 0 = flat, 90 = a cube edge
  bool gentle = false;        // bend_degrees < strong_fold_angle_degrees: curve, do not crease
};

/// A piece of texture: the affine map taking `uvs` (texture coordinates in [0, 1], v up)
/// to `corners` (page mm), painted inside the convex polygon `clip` (page mm).
struct TexturePatch {
  std::array<Vec2, 3> corners;
  std::array<Vec2, 3> uvs;  // zero when the strips have no uvs
  std::vector<Vec2> clip;
  /// The 3D points of the corners (model units): the print image is baked from the input
  /// surface nearest them (nodes/export/bake.h).
  std::array<Vec3, 3> points3d = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
};

/// A glue tab on one side of a seam, as one or more flaps (a bent seam gets one flap per
/// nearly straight run of edges). Each flap polygon is counter-clockwise on the page as a
/// reader sees it (clockwise on a page printed on the back, which is mirrored): its base
/// polyline (on the seam) in reverse, then its outer chain; `bases` are the base polylines,
/// the tab's fold lines (mountain; valley on the back).
struct Tab {
  std::string label;
  std::vector<std::vector<Vec2>> flaps;
  std::vector<std::vector<Vec2>> bases;
  /// Where the strips have uvs: per flap and base edge, the texture continuing across the
  /// seam (the partner triangle unfolded onto the tab), clipped to the flap.
  std::vector<TexturePatch> texture;
};

/// A boundary edge of a placed piece in page mm, the piece on its left as a reader sees it
/// (on its right on a page printed on the back).
struct PlacedEdge {
  Vec2 a = Vec2::Zero();
  Vec2 b = Vec2::Zero();
  EdgeKind kind = EdgeKind::Cut;
  std::string label;     // printed seam label ("" unless kind == Seam)
  bool has_tab = false;  // a flap of this piece's tab is glued along this edge
};

/// Maps a strip's vertices2d (model units) to page mm: page = linear * v + translation.
/// linear = diag(1, -1) * rotation * mm_per_unit (the y flip of page coordinates); on a page
/// printed on the back diag(-1, -1) * rotation * mm_per_unit and the translation mirrored.
struct PageTransform {
  Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();
  Vec2 translation = Vec2::Zero();
  double rotation_degrees = 0.0;  // counter-clockwise, in the strip's y-up frame

  Vec2 apply(const Vec2& v) const { return linear * v + translation; }
};

/// One piece of paper on a page: a whole flat strip or, where the strip was split to fit
/// a page, a part of it.
/// A seam on a placed piece: its printed label and the piece it is glued to.
struct PieceSeam {
  std::string label;    // as printed on both sides
  std::string partner;  // name of the piece across ("" when it has none)
  bool tab = false;     // this piece carries the seam's glue tab
};

struct PlacedPiece {
  std::string name;  // printed number: 1..N with no gaps; "12a", "12b" for a split strip
  int strip_id = -1;
  int piece_index = 0;  // 0..piece_count-1 along the strip
  int piece_count = 1;
  PageTransform transform;
  /// The piece's own vertex arrays: page mm, the strip vertex each came from, uvs (empty
  /// if the strip has none) and triangles indexing `vertices`.
  std::vector<Vec2> vertices;
  /// -1 for a point layout_pages added where it divided the strip's triangles (a coarse mesh
  /// printed larger than a page); `points3d` has every vertex's 3D point (model units).
  std::vector<int> strip_vertex;
  std::vector<Vec3> points3d;
  std::vector<Vec2> uvs;
  std::vector<Triangle> triangles;
  /// Boundary loops of the piece without tabs (outer loop first).
  std::vector<std::vector<Vec2>> outline;
  /// What to cut: one closed path per boundary loop around the piece and its tabs.
  std::vector<std::vector<Vec2>> cut_outline;
  std::vector<PlacedEdge> edges;
  std::vector<FoldLine> folds;  // inner edges only; tab bases are in `tabs`
  std::vector<Tab> tabs;
  std::vector<Label> labels;  // one per seam side on this piece
  /// Alignment marks: a short tick across the cut line at each end of a seam chain where it
  /// meets another seam, printed on both pieces so that long seams are glued in register.
  std::vector<std::array<Vec2, 2>> marks;
  Label number;  // the name, as printed
  std::vector<PieceSeam> seams;
};

/// A bar of a round length with ticks, and its caption, in page mm.
struct ScaleBar {
  Vec2 start = Vec2::Zero();  // left end of the bar (on its baseline)
  double length_mm = 50.0;
  double tick_spacing_mm = 10.0;
  double tick_height_mm = 2.0;
  Label caption;
};

struct Page {
  std::vector<PlacedPiece> pieces;
  /// Joining strips: for a seam with room for a glue tab on neither side, a loose strip of
  /// paper glued behind both sides of the seam. `name` is the seam's printed label, `marks`
  /// hold its centre line (where the seam goes); no strip of the model (strip_id -1).
  std::vector<PlacedPiece> joints;
  ScaleBar scale_bar;
  Label footer;  // "page 2 / 5"
};

/// How usable the pages are, measured on the placed pieces.
struct LayoutStats {
  std::vector<double> page_fill;  // per page: pieces and tabs / printable area (0..1)
  int seams = 0;                  // printed seam labels (each counted once)
  int seams_without_tab = 0;      // ... of which neither side carries a tab nor has a joint
  int joining_strips = 0;         // seams glued with a joining strip (Page::joints)
  double smallest_text_mm = 0.0;  // the smallest label or number
  int overlapping_text = 0;       // pairs of labels/numbers whose boxes intersect
};

struct PatternLayout {
  PageSize page;
  double margin_mm = 10.0;
  double mm_per_unit = 1.0;
  /// Back: pieces, tabs, folds and labels mirrored across the page's vertical centre line;
  /// fold kinds are as seen from the printed side (the model's inside), so a convex edge is a
  /// Valley and a tab's base (Tab::bases) a valley fold. Texts still read left to right.
  PrintSide print_side = PrintSide::Front;
  std::vector<Page> pages;
  /// Pages the plain shelf packing and the rectangle packing need for the same pieces.
  int shelf_page_count = 0;
  int rectangle_page_count = 0;
  /// Strips that did not fit a page and were split, pieces that still do not fit
  /// (they overflow their page), seams without a partner or without room for a tab.
  std::vector<std::string> warnings;
  LayoutStats stats;
};

}  // namespace papercraft
