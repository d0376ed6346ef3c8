// layout_pass: one way of laying out the strips, as a list of steps over one state.
#include "nodes/layout/layout_pass.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <string>

#include "nodes/layout/format_mm.h"
#include "nodes/layout/nesting.h"
#include "nodes/layout/place_piece.h"
#include "nodes/layout/polygon_2d.h"
#include "nodes/layout/prepare_layout.h"
#include "nodes/layout/rectangle_packing.h"
#include "nodes/layout/seam_pairing.h"
#include "nodes/layout/split_to_fit.h"
#include "nodes/layout/tab_styles.h"

namespace papercraft::layout_internal {
namespace {

// A strip that packs badly: longer than half the page's long side and thin or bent (its area
// under 40% of its box, or the box over 3 times as long as wide). One larger than the page
// counts too: split only to fit the page, its parts stay as long and bent.
bool long_and_thin(const StripData& data, const PreparedLayout& p, double* waste) {
  const double w = p.area.x() - 2 * p.reserve, h = p.area.y() - 2 * p.reserve;
  bool fits = false;
  const OrientedBox box =
      tightest_box(convex_hull(piece_points(data, data.triangles)), w, h, &fits);
  double area = 0.0;
  for (const int t : data.triangles) {
    const Triangle& tri = data.strip->triangles[t];
    area += 0.5 * std::abs(cross(data.points[tri[1]] - data.points[tri[0]],
                                 data.points[tri[2]] - data.points[tri[0]]));
  }
  const double length = box.size.maxCoeff(), width = box.size.minCoeff();
  *waste = box.size.prod() - area;
  return length > 0.5 * std::max(w, h) && (area < 0.4 * box.size.prod() || length > 3.0 * width);
}

// A joining strip for a seam `length` mm long: a rectangle (length + 2 mm, at least 8 mm) by
// 2 x tab_width_mm, flat, cut all round (model units at mm_per_unit); its centre line is where
// the seam goes.
FlatStrip joining_strip(int id, double length, const LayoutOptions& options, double mm_per_unit) {
  const double l = std::max(length + 2.0, 8.0) / mm_per_unit;
  const double w = 2.0 * options.tab_width_mm / mm_per_unit;
  FlatStrip strip;
  strip.id = id;
  strip.source_strip = -1;
  strip.vertices2d = {Vec2(0, 0), Vec2(l, 0), Vec2(l, w), Vec2(0, w)};
  for (const Vec2& v : strip.vertices2d) strip.vertices3d.emplace_back(v.x(), v.y(), 0.0);
  strip.triangles = {{0, 1, 2}, {0, 2, 3}};
  for (int i = 0; i < 4; ++i) strip.boundary.push_back({i, (i + 1) % 4, EdgeKind::Cut, -1, "", -1});
  return strip;
}

// The seams of one pass: seam edges matched, chained along the pieces' loops and paired.
struct Seams {
  SeamEdges edges;
  std::vector<Chain> chains;
  std::vector<SeamPair> pairs;
};

// The pieces of paper the strips are printed as: each strip whole where it fits the page,
// else split to fit it, and long thin strips split as `split_long` says. Pieces are numbered
// 1..N in strip order, with no gaps.
std::vector<Piece> cut_pieces(const std::vector<FlatStrip>& strips, PreparedLayout& p,
                              const LayoutOptions& options, SplitLong split_long,
                              const std::vector<char>* chosen, LongStrips* long_strips,
                              std::vector<std::string>& warnings) {
  std::set<std::string> used_labels;
  for (const FlatStrip& strip : strips)
    for (const BoundaryEdge& e : strip.boundary)
      if (e.kind == EdgeKind::Seam) used_labels.insert(e.label);

  std::vector<Piece> pieces;
  int number = 0;
  for (int s = 0; s < static_cast<int>(p.strips.size()); ++s) {
    StripData& data = p.strips[s];
    if (data.triangles.empty()) {
      warnings.push_back(strip_name(*data.strip) + " has no triangles; skipped");
      continue;
    }
    ++number;
    std::vector<std::vector<int>> sets;
    const bool fits = strip_fits(data, p);
    double waste = 0.0;
    bool long_thin = options.packing == PackingMethod::Nest && options.split_long_strips &&
                     long_and_thin(data, p, &waste);
    (fits ? long_strips->found : long_strips->oversize) += long_thin;
    if (long_thin) long_strips->waste.push_back({waste, s});
    if (chosen && !(*chosen)[s]) long_thin = false;
    const double w = p.area.x() - 2 * p.reserve, h = p.area.y() - 2 * p.reserve;
    if (long_thin && split_long == SplitLong::Bends) {
      for (std::vector<int>& part : split_at_bends(data, used_labels)) {
        if (strip_fits(data, p, part)) {
          sets.push_back(std::move(part));
          continue;
        }
        for (std::vector<int>& piece : split_to_fit(data, part, w, h, used_labels))
          sets.push_back(std::move(piece));
      }
      long_strips->split += sets.size() > 1;
    } else if (long_thin &&
               (split_long == SplitLong::All || (split_long == SplitLong::Fitting && fits))) {
      // Half the page: its long side halved.
      sets = h >= w ? split_to_fit(data, w, 0.5 * h, used_labels)
                    : split_to_fit(data, 0.5 * w, h, used_labels);
      long_strips->split += sets.size() > 1;
    } else if (fits) {
      sets.push_back(data.triangles);
    } else {
      sets = split_to_fit(data, w, h, used_labels);
    }
    if (!fits) {
      bool unused = false;
      const OrientedBox box =
          tightest_box(convex_hull(piece_points(data, data.triangles)), w, h, &unused);
      warnings.push_back(strip_name(*data.strip) + " (" + format_mm(box.size.x()) + " x " +
                         format_mm(box.size.y()) +
                         " mm) fits no page orientation with room "
                         "for tabs (" +
                         format_mm(w) + " x " + format_mm(h) + " mm); split into " +
                         std::to_string(sets.size()) + " pieces at inner edges");
    }
    for (int k = 0; k < static_cast<int>(sets.size()); ++k) {
      Piece piece;
      piece.strip = s;
      piece.index = k;
      piece.count = static_cast<int>(sets.size());
      piece.name = piece_name(number, k, piece.count);
      piece.triangles = std::move(sets[k]);
      piece.loops = piece_loops(data, piece.triangles, warnings);
      pieces.push_back(std::move(piece));
    }
  }
  return pieces;
}

// Seams paired and each side labelled and marked; tabs added where options ask for them; each
// piece told its seams, their partners and whether it carries their tab.
Seams pair_seams(std::vector<Piece>& pieces, const PreparedLayout& p, const LayoutOptions& options,
                 std::vector<std::string>& warnings) {
  Seams seams;
  seams.edges = match_seam_edges(pieces, p.strips);
  seams.chains = seam_chains(pieces, p.strips, seams.edges, p.tolerance3d);
  seams.pairs = pair_chains(seams.chains, seams.edges, pieces, p.tolerance3d, warnings);
  const std::vector<Chain>& chains = seams.chains;
  for (const SeamPair& pair : seams.pairs) {
    for (int side : {pair.first, pair.second}) {
      if (side < 0) continue;
      const Chain& chain = chains[side];
      Piece& piece = pieces[chain.piece];
      auto& loop = piece.loops[chain.loop];
      for (int i = 0; i < chain.count; ++i)
        loop[(chain.start + i) % loop.size()].printed = pair.printed;
      piece.labels.push_back(
          chain_label(p.strips[piece.strip], piece, chain, pair.printed, options.label_size_mm));
      piece.labels.back().chain = side;
      add_alignment_marks(p.strips[piece.strip], piece, chain, options.alignment_mark_mm);
    }
  }
  const bool tabs = options.tab_width_mm > 0 && options.tab_style != TabStyle::None;
  if (tabs) add_tabs(pieces, p.strips, chains, seams.pairs, seams.edges, options, warnings);
  for (const SeamPair& pair : seams.pairs) {
    const int a = chains[pair.first].piece;
    const int b = pair.second >= 0 ? chains[pair.second].piece : -1;
    auto has_tab = [&](int piece) {
      for (const PieceTab& tab : pieces[piece].tabs)
        if (tab.label == pair.printed && !tab.flaps.empty()) return true;
      return false;
    };
    pieces[a].seams.push_back({pair.printed, b >= 0 ? pieces[b].name : "", has_tab(a)});
    if (b >= 0) pieces[b].seams.push_back({pair.printed, pieces[a].name, has_tab(b)});
  }
  return seams;
}

// Seams with room for a tab on neither side get a joining strip glued behind them: a piece
// of its own (Piece::joint), its strip kept in `joint_strips` (p.strips points into it).
void add_joining_strips(const std::vector<FlatStrip>& strips, PreparedLayout& p,
                        std::vector<Piece>& pieces, const Seams& seams,
                        const LayoutOptions& options, std::deque<FlatStrip>& joint_strips,
                        std::vector<std::string>& warnings) {
  int next_id = 0;
  for (const FlatStrip& strip : strips) next_id = std::max(next_id, strip.id + 1);
  const std::size_t model_pieces = pieces.size();
  for (const SeamPair& pair : seams.pairs) {
    if (pair.second < 0) continue;
    const Chain& chain = seams.chains[pair.first];
    bool tabbed = false;
    for (int side : {pair.first, pair.second})
      for (const PieceTab& tab : pieces[seams.chains[side].piece].tabs)
        tabbed = tabbed || (tab.label == pair.printed && !tab.flaps.empty());
    if (tabbed) continue;
    const Piece& owner = pieces[chain.piece];
    const double length = chain_length(p.strips[owner.strip], owner, chain);
    joint_strips.push_back(joining_strip(next_id++, length, options, p.mm_per_unit));
    p.strips.push_back(prepare_strip(joint_strips.back(), p.mm_per_unit));
    StripData& data = p.strips.back();
    Piece joint;
    joint.strip = static_cast<int>(p.strips.size()) - 1;
    joint.name = pair.printed;
    joint.joint = true;
    joint.triangles = data.triangles;
    joint.loops = piece_loops(data, joint.triangles, warnings);
    const Vec2 a = 0.5 * (data.points[0] + data.points[3]);
    const Vec2 b = 0.5 * (data.points[1] + data.points[2]);
    joint.marks.push_back({a + Vec2(0.5, 0), b - Vec2(0.5, 0)});
    pieces.push_back(std::move(joint));
  }
  if (pieces.size() > model_pieces)
    warnings.push_back(std::to_string(pieces.size() - model_pieces) +
                       " seams with no room for a tab get a joining strip glued behind them");
}

// The pieces oriented with their labels arranged: those that fit the printable area to be
// packed, the others (overflowing) each on a page of its own.
struct Oriented {
  std::vector<Orientation> orientations;  // of every piece
  std::vector<int> packed, oversized;     // piece indices
  std::vector<Vec2> sizes;                // of the packed pieces' boxes
  int overflowing = 0;                    // oversized pieces that fit no page
};

Oriented orient_pieces(std::vector<Piece>& pieces, const PreparedLayout& p, const Seams& seams,
                       const LayoutOptions& options, LabelCache* labels,
                       std::vector<std::string>& warnings) {
  Oriented o;
  for (int i = 0; i < static_cast<int>(pieces.size()); ++i) {
    const StripData& data = p.strips[pieces[i].strip];
    o.orientations.push_back(orient_piece(data, pieces[i], p.area));
    arrange_labels(data, pieces[i], seams.chains, o.orientations.back().box, options, warnings,
                   labels);
    if (pieces[i].joint && pieces[i].number) {
      // The seam's label at the middle of its joining strip, on the centre line.
      const auto& points = data.points;
      PieceLabel& name = *pieces[i].number;
      name.position = 0.25 * (points[0] + points[1] + points[2] + points[3]);
      name.direction = Vec2::UnitX();
      name.size = std::max(options.min_text_mm,
                           std::min(options.number_size_mm, 0.6 * (points[2] - points[1]).norm()));
      name.outside = false;
    }
    // Text printed beside the piece takes paper too.
    if (!outside_text(pieces[i]).empty())
      o.orientations.back() = orient_piece(data, pieces[i], p.area);
    const Orientation& orientation = o.orientations.back();
    if (orientation.fits && orientation.box.size.minCoeff() > 0) {
      o.packed.push_back(i);
      o.sizes.push_back(orientation.box.size);
    } else {
      o.oversized.push_back(i);
      if (!orientation.fits) {
        ++o.overflowing;
        warnings.push_back("piece " + pieces[i].name + " (" + format_mm(orientation.box.size.x()) +
                           " x " + format_mm(orientation.box.size.y()) +
                           " mm with tabs) does not fit the printable area (" +
                           format_mm(p.area.x()) + " x " + format_mm(p.area.y()) +
                           " mm) and overflows its page: lower height_mm or use a larger page");
      }
    }
  }
  return o;
}

// The packed pieces nested by their true outlines (nesting.h); empty where the nesting left
// a piece out or needs more pages than `rectangle_pages`.
std::vector<NestPlacement> nest_pieces(const std::vector<Piece>& pieces, const PreparedLayout& p,
                                       const Seams& seams, const Oriented& oriented,
                                       const LayoutOptions& options, int rectangle_pages,
                                       int* nested_pages) {
  std::vector<NestShape> shapes;
  for (const int i : oriented.packed) {
    const StripData& data = p.strips[pieces[i].strip];
    NestShape shape;
    for (const int t : pieces[i].triangles) {
      const Triangle& tri = data.strip->triangles[t];
      shape.convex.push_back({data.points[tri[0]], data.points[tri[1]], data.points[tri[2]]});
    }
    for (const Flap& flap : pieces[i].flaps) {
      std::vector<Vec2> outline(flap.base.begin(), flap.base.end());
      outline.insert(outline.end(), flap.outer.begin(), flap.outer.end());
      shape.convex.push_back(convex_hull(outline));
    }
    for (const auto& mark : pieces[i].marks) shape.convex.push_back({mark[0], mark[1]});
    for (const auto& box : outside_text(pieces[i]))
      shape.convex.push_back(std::vector<Vec2>(box.begin(), box.end()));
    shapes.push_back(std::move(shape));
  }
  NestOptions nest;
  nest.spacing_mm = options.spacing_mm;
  nest.rotations = options.nest_rotations;
  nest.cell_mm = options.nest_cell_mm;
  nest.repacks = options.nest_repacks;
  std::vector<int> shape_of(pieces.size(), -1);
  for (std::size_t k = 0; k < oriented.packed.size(); ++k)
    shape_of[oriented.packed[k]] = static_cast<int>(k);
  for (const SeamPair& pair : seams.pairs) {
    if (pair.second < 0) continue;
    const int a = shape_of[seams.chains[pair.first].piece];
    const int b = shape_of[seams.chains[pair.second].piece];
    if (a >= 0 && b >= 0 && a != b) nest.neighbours.push_back({a, b});
  }
  std::vector<NestPlacement> nested = nest_shapes(shapes, p.area, nest, nested_pages);
  const bool complete =
      std::all_of(nested.begin(), nested.end(), [](const NestPlacement& n) { return n.page >= 0; });
  if (!complete || *nested_pages > rectangle_pages) nested.clear();
  return nested;
}

// The oriented pieces packed (by rectangles, and nested where options ask and that needs no
// more pages) and placed on the layout's pages, oversized pieces each on a page of its own.
void pack_and_place(const std::vector<Piece>& pieces, const PreparedLayout& p, const Seams& seams,
                    const Oriented& oriented, const LayoutOptions& options, PatternLayout& layout) {
  const std::vector<int>& packed = oriented.packed;
  const std::vector<int>& oversized = oriented.oversized;
  const PackingMethod rectangles =
      options.packing == PackingMethod::Nest ? PackingMethod::MaxRects : options.packing;
  const PackResult result =
      pack_with_spacing(oriented.sizes, p.area.x(), p.area.y(), options.spacing_mm, rectangles);
  layout.shelf_page_count = (rectangles == PackingMethod::Shelf
                                 ? result.pages
                                 : pack_with_spacing(oriented.sizes, p.area.x(), p.area.y(),
                                                     options.spacing_mm, PackingMethod::Shelf)
                                       .pages) +
                            static_cast<int>(oversized.size());
  layout.rectangle_page_count = result.pages + static_cast<int>(oversized.size());
  // Nesting by outlines; kept only where it needs no more pages than the rectangles.
  std::vector<NestPlacement> nested;
  int nested_pages = 0;
  if (options.packing == PackingMethod::Nest && !packed.empty())
    nested = nest_pieces(pieces, p, seams, oriented, options, result.pages, &nested_pages);
  const int packed_pages = nested.empty() ? result.pages : nested_pages;
  layout.pages.resize(packed_pages + oversized.size());
  // A placed piece onto its page; a joining strip among the page's joints, of no model strip.
  auto put = [&](int page, int i, PlacedPiece placed) {
    if (!pieces[i].joint) {
      layout.pages[page].pieces.push_back(std::move(placed));
      return;
    }
    placed.strip_id = -1;
    layout.pages[page].joints.push_back(std::move(placed));
  };
  for (std::size_t k = 0; k < packed.size(); ++k) {
    const int i = packed[k];
    const StripData& data = p.strips[pieces[i].strip];
    const OrientedBox& box = oriented.orientations[i].box;
    if (!nested.empty()) {
      const NestPlacement& at = nested[k];
      put(at.page, i,
          place_piece_at(data, pieces[i], box, at.angle,
                         at.offset + Vec2(options.margin_mm, options.margin_mm), options,
                         p.mm_per_unit));
      continue;
    }
    put(result.placements[k].page, i,
        place_piece(data, pieces[i], box, result.placements[k], options, p.mm_per_unit));
  }
  for (std::size_t k = 0; k < oversized.size(); ++k) {
    const int i = oversized[k];
    put(packed_pages + static_cast<int>(k), i,
        place_piece(p.strips[pieces[i].strip], pieces[i], oriented.orientations[i].box,
                    {0, 0, 0, false}, options, p.mm_per_unit));
  }
}

}  // namespace

LayoutPass layout_pass(const std::vector<FlatStrip>& strips, const LayoutOptions& options,
                       SplitLong split_long, const std::vector<char>* chosen, LabelCache* labels,
                       bool divided) {
  LayoutPass pass;
  PreparedLayout p = prepare_layout(strips, options);
  for (StripData& data : p.strips) data.divided = divided;
  PatternLayout& layout = pass.layout;
  layout.page = options.page;
  layout.margin_mm = options.margin_mm;
  layout.mm_per_unit = p.mm_per_unit;
  std::vector<std::string>& warnings = layout.warnings;

  std::vector<Piece> pieces =
      cut_pieces(strips, p, options, split_long, chosen, &pass.long_strips, warnings);
  const Seams seams = pair_seams(pieces, p, options, warnings);
  std::deque<FlatStrip> joint_strips;  // the joining strips' storage (StripData points into it)
  if (options.joining_strips && options.tab_width_mm > 0 && options.tab_style != TabStyle::None)
    add_joining_strips(strips, p, pieces, seams, options, joint_strips, warnings);
  const Oriented oriented = orient_pieces(pieces, p, seams, options, labels, warnings);
  pack_and_place(pieces, p, seams, oriented, options, layout);
  for (int i = 0; i < static_cast<int>(layout.pages.size()); ++i)
    add_page_furniture(layout.pages[i], i, static_cast<int>(layout.pages.size()), options,
                       p.mm_per_unit);
  layout.stats = layout_stats(layout, p.area);
  pass.cost = layout_cost(layout, oriented.overflowing);
  return pass;
}

}  // namespace papercraft::layout_internal
