#pragma once
// How narrow a flat piece is: the share of its area that no disc of a given diameter inside
// the piece covers, i.e. the piece minus its morphological opening by that disc. A long band
// 2 mm wide is narrow everywhere at 3 mm; a wide piece is narrow only in its sharp corners
// and at the tips of a cone, which cover little area.

#include <cstddef>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

struct PieceWidthOptions {
  /// Raster cell size as a fraction of the disc's diameter; the raster is coarsened so that it
  /// never holds more than `max_cells` cells.
  double cell_fraction = 0.125;
  long max_cells = 4'000'000;
};

/// Share of the area of the flat piece (`points`, `triangles`: a 2D triangle soup, any
/// orientation; overlapping triangles count once) that lies farther than `width / 2` from the
/// centre of every disc of diameter `width` contained in the piece. 0 for a piece at least
/// `width` wide everywhere (up to its corners), 1 for a band narrower than `width`. Measured on
/// a raster (Euclidean distances between cell centres, within the few cells a disc spans), so
/// it is exact to about one cell. Returns 0 for a piece without area.
/// \throws InvalidInputException if width is not positive and finite, a triangle index is out
///   of range or a point is not finite.
double narrow_area_fraction(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles,
                            double width, const PieceWidthOptions& options = {});

/// The raster narrow_area_fraction measures a flat piece on: square cells of side `cell`, cell
/// (i, j) centred at origin + (i + 1/2, j + 1/2) cell; `inside` counts the cells whose centre
/// the piece covers, `narrow` those of them that no disc of the diameter inside covers.
struct NarrowRaster {
  Vec2 origin = Vec2::Zero();
  double cell = 0.0;
  long inside = 0;
  long narrow = 0;
  /// narrow / inside; 0 without inside cells.
  double fraction() const { return inside > 0 ? double(narrow) / double(inside) : 0.0; }
};

/// The raster of narrow_area_fraction (which is its fraction()): over the piece's bounding box
/// and one `width` around it. \throws InvalidInputException as narrow_area_fraction.
NarrowRaster narrow_raster(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles,
                           double width, const PieceWidthOptions& options = {});

/// The counts of the piece's cells on `grid`'s cells (its origin and cell) whose centre lies in
/// the box [lo, hi]. A cell's narrowness depends only on the piece within `width` of it, so only
/// the triangles within two widths of the box are rastered, and the counts are those the whole
/// piece has on that grid there. So when a piece changes only within `width` inside a box's
/// edges (triangles added in its middle), narrow_raster of it before, less this over the box
/// before, plus this over the box after, is the changed piece's raster on the same grid, at a
/// cost that grows with the box, not with the piece.
/// \throws InvalidInputException as narrow_area_fraction, or if the box is not finite with
///   lo <= hi, or the grid's origin is not finite or its cell not positive.
NarrowRaster narrow_raster_in_box(const std::vector<Vec2>& points,
                                  const std::vector<Triangle>& triangles, double width,
                                  const Vec2& lo, const Vec2& hi, const NarrowRaster& grid);

/// The narrow part of the piece (the cells narrow_area_fraction counts as narrow) split into
/// connected regions (cells joined across sides: a staircase of cells along a slanted edge is
/// no band): the area of the largest, in the
/// points' units squared. A tip (a cone's apex, a corner) is a small region, a sliver (a band
/// narrower than `width` along a length) a long one, however small its share of the piece.
/// `raster`, where given, gets narrow_raster of the piece (measured on the way).
/// \throws InvalidInputException as narrow_area_fraction.
double largest_narrow_region(const std::vector<Vec2>& points,
                             const std::vector<Triangle>& triangles, double width,
                             const PieceWidthOptions& options = {}, NarrowRaster* raster = nullptr);

/// The same share for a piece of surface in 3D, with Euclidean distances: sample points
/// (spaced at most `cell_fraction` times `width` apart over every triangle) farther than
/// `width / 2` from the piece's boundary edges (edges of one triangle) are disc centres, and
/// a sample within `width / 2` of a centre is wide. On a flat piece this is the 2D share up to
/// the sampling; on a curved one the Euclidean distance to the boundary is at most the
/// distance along the surface, so a bent piece reads at most as wide as it unfolds (a tube
/// narrower than `width` reads as narrow even when its unrolled band would be wide). A closed
/// piece (no boundary) returns 0. At most `max_cells` samples: larger pieces are sampled more
/// coarsely.
/// \throws InvalidInputException if width is not positive and finite or an index is out of
///   range.
double narrow_area_fraction(const TriangleMesh& piece, double width,
                            const PieceWidthOptions& options = {});

/// narrow_area_fraction of a 3D piece, with its narrow samples split into connected regions
/// (samples closer than 1.5 times their spacing are joined): `largest_region` is the area of the
/// largest, in the vertices' units squared. A tip (a cone's apex, a corner where cuts meet) is a
/// small region, a thin tail along a wide strip a long one, whatever its share of the piece.
/// Samples of two sheets of the piece that pass closer than their spacing join too, so a region
/// reads at least as large as along the surface.
struct NarrowMeasure {
  double fraction = 0.0;        // == narrow_area_fraction(piece, width, options)
  double largest_region = 0.0;  // 0 without narrow samples
  /// Points measured: about the area over the spacing squared, thin triangles included (one
  /// is sampled in rows along its longest edge).
  std::size_t samples = 0;
};

/// \throws InvalidInputException as narrow_area_fraction.
NarrowMeasure narrow_measure(const TriangleMesh& piece, double width,
                             const PieceWidthOptions& options = {});

}  // namespace papercraft
