#pragma once
// Merging of flat strips along congruent shared boundaries: the `merge` stage's algorithm
// (paper section 3.4 and fig. 3, a cylinder with holes; DESIGN.md "Merge").
//
// Each function below is implemented in a file of its own in nodes/merge/, over the moves it
// shares with the others (docs/stages/merge.md, "Source").
//
// Example (node config): merge: {impl: merge.congruent, to: [layout]}

#include <cstddef>
#include <vector>

#include "core/effort.h"
#include "core/strip.h"

namespace papercraft {

struct MergeOptions {
  /// The two flat images of a shared boundary are congruent when, after the best rigid
  /// motion (a rotation and a translation, never a reflection), no point is farther from
  /// its partner than this times the boundary's length. Welding moves the joined strip's
  /// boundary points by up to that much, so it bounds how far a seam's two sides may differ
  /// in length.
  double congruence_tolerance = 1e-11;
  /// The union must not overlap itself: two triangles may penetrate by at most this
  /// times the mean edge length (plus the rigid fit's residual).
  double overlap_tolerance = 1e-9;
  /// The merge node hinges a piece narrower than min_width_mm over more than this share of
  /// its area onto a neighbour (join_narrow_strips); 1: never.
  double narrow_join_share = 0.25;
  /// After the joins of crumbs and narrow pieces, a piece under this times min_area (a legal
  /// but small piece, one more to cut and glue) is hinged onto a neighbour where the union
  /// lies flat (hinge_modest_strips); <= 1: never.
  double modest_join_factor = 2.0;
  /// A band no hinge takes whole is cut into at most this many pieces, each hinged onto a
  /// neighbour (join_narrow_strips): 2 to 4. The merge node refines in 3D against a merge that
  /// cuts in three at most (a join in 3D leaves no seam, a band cut in four leaves many), then
  /// merges with the full depth where pieces are still left short.
  int most_band_pieces = 4;
  /// The merge node's joins in 3D (a short piece's part refined together with a neighbour's)
  /// each cost a merge of the whole model to judge; at most this many are judged per model.
  /// Where the budget runs out the node keeps the best merge reached and says so in a note.
  int most_rejoin_trials = 4;
  /// The print scale (page mm per model unit). With it the hinges are chosen by what they cost a
  /// person (local_effort, core/piece_effort.h: the seams they open, the joining strips a slit
  /// too thin for a glue flap needs, sawtooth corners), a modest piece is hinged only where that
  /// costs less than keeping it, and the node's choices between whole merges (joins in 3D, how
  /// deep a band is cut) go by the same cost; 0: hinges by the slit they leave (slit_points) and
  /// merges by the pieces left short. The node sets it from the model.
  double mm_per_unit = 0.0;
  /// The weights of that cost (the config's `effort:` map; the node sets them).
  EffortWeights weights{};
};

/// Joins flat strips of one model whose shared boundaries have congruent flat images.
///
/// A shared boundary is a chain of consecutive boundary edges of strip X glued, with
/// opposite directions, to consecutive boundary edges of another strip Y (same 3D
/// endpoints, compared exactly as label_seams does). Pairs are tried greedily, the pair
/// with the longest total shared length first; for a pair, its chains are tried longest
/// first as the one to fit: Y is moved rigidly onto X along it and kept only if the
/// union overlaps nowhere. Every chain of the pair that then coincides in the plane is
/// welded (shared vertices become one, the seam edges become inner edges), so a strip
/// fitting into a gap of the other closes it. Repeats until no pair merges, then calls
/// label_seams on the result, so every boundary edge is Seam or Open.
///
/// A merged strip keeps X's place in the vector, id, source_strip and 2D frame (X being
/// the earlier strip); the others are unchanged apart from their boundary, which is
/// recomputed from the triangles. uvs are kept when both strips have them.
///
/// \pre every strip has vertices2d and vertices3d of equal size, uvs empty or of that
///      size, triangle indices in range; options' tolerances >= 0.
/// \throws InvalidInputException if a precondition fails.
/// Known limit: greedy, so the merge order can leave a merge out that another order
/// would have allowed; chains must share vertices exactly (no collinear sub-segments).
std::vector<FlatStrip> merge_congruent(std::vector<FlatStrip> strips,
                                       const MergeOptions& options = {});

/// Drops the triangles printed twice: a triangle whose three 3D corners are those of a triangle
/// before it (in an earlier strip, or earlier in the same one) is taken out of its strip. The
/// strips of two parts can both cover the same stretch of surface between them: the ruled
/// approximation of each fills the space between the points of their shared cut where the cut
/// zigzags (a flat region where the harmonic field hardly varies, on CAD models), so both pieces
/// would print the same triangles and their seams could not be told apart. The union of the
/// strips, so the certified distance, is unchanged. A strip left empty goes; one that falls
/// apart is split into its pieces (joined across edges), the largest keeping its id and the
/// others taking new ids after every strip's; one that would meet itself at a point keeps its
/// triangles (and so the double cover). The rest of each strip keeps its layout; its boundary
/// is recomputed. `dropped` (when given) gets the number of triangles taken out.
/// \pre as merge_congruent. \throws InvalidInputException as merge_congruent.
std::vector<FlatStrip> drop_double_covered_triangles(std::vector<FlatStrip> strips,
                                                     std::size_t* dropped = nullptr);

/// Joins each flat strip of less than `min_area` (model units squared) to a neighbour, the
/// smallest first: Y moved rigidly so that one edge it shares with X lies on X's image of it
/// (lengths agree, the strips being isometric), kept where the union overlaps nowhere. Edges
/// are tried those at an end of an open shared chain first, then the longest; with `min_width`
/// > 0, of the first that lays it flat and the 16 tried after it, the one whose union leaves
/// the fewest shared points closer than `min_width` in the plane (a slit: a hinge in the middle
/// of a chain that does not weld opens a thin wedge on both sides of it), else the first. The
/// joined piece folds over that edge (a hinge); its other shared edges become seams of the union
/// with itself, glued as any seam. Merged strips keep the lower index's id and frame, as in
/// merge_congruent. A small strip that no neighbour takes whole (every hinge lays it over the
/// neighbour: at a saddle the gap in the plane is narrower than the strip) is taken apart into its
/// triangles (at most 64), each folded out of a neighbour over one of its edges, longest first; a
/// triangle next to its siblings only waits for one of them to be taken. That is kept only when
/// every triangle finds a place and at most one edge between two of its triangles is opened (each
/// one a new seam to glue, often tiny and in a notch without room for a tab). A small strip that
/// cannot be taken apart (more than 64 triangles, or more edges opened) is cut in two (or three, or
/// four) across its inner edges, each part hinged onto a neighbour (join_narrow_strips' cut, with
/// no neighbour getting narrower than `min_width` over more than options.narrow_join_share of its
/// area or than it was; `min_width` 0: not tried). One that cannot be cut either grows instead: it
/// takes its neighbours' triangles that share an edge with it, one at a time (of those that find a
/// place, the one leaving it most compact: the least squared perimeter per area in the plane), each
/// folded out of it over the edges it shares, until it reaches `min_area`; a triangle takes with it
/// what its neighbour held only through it (the end of a ruled strip beyond it), so the neighbour
/// stays one piece. It is taken only where it lands on no other triangle of the strip, every edge
/// shared welds (no slit) and the neighbour keeps at least `min_area`. It grows until it reaches
/// `min_area` and neither it nor a neighbour it took from is narrower than `min_width` over more
/// than options.narrow_join_share of its area (or than before; `min_width` 0: not checked): past
/// `min_area` it goes on growing until that holds, giving up once 16 triangles in a row bring no
/// such growth. Kept only within 128 triangles. The 3D surface is unchanged: only which piece
/// prints a triangle moves, so the seam between them moves with it. The ids of small strips left go
/// to `left` (when given); then label_seams runs on the result.
///
/// \pre as merge_congruent.
/// \throws InvalidInputException as merge_congruent.
std::vector<FlatStrip> join_small_strips(std::vector<FlatStrip> strips, double min_area,
                                         const MergeOptions& options = {},
                                         std::vector<int>* left = nullptr, double min_width = 0.0);

/// Joins each flat strip narrower than `min_width` (model units) over more than `narrow_share`
/// of its area (narrow_area_fraction: a band along a thin feature, a fan of long thin
/// triangles) to a neighbour by a hinge, as join_small_strips joins a crumb: the narrowest
/// first, its shared edges the longest first (at most `most_hinges` tried), kept where the
/// union overlaps nowhere, is less narrow than the strip, and either no more narrow than the
/// neighbour was (or than `narrow_share`) or narrow over no more area than the strip and the
/// neighbour together (a band kept whole beside a wide neighbour, one seam fewer); of those,
/// the hinge leaving the fewest shared points closer than `min_width` in the plane (a slit).
/// The band then folds over the hinge and its other shared edges are seams of the union with
/// itself. A strip no hinge takes whole (its neighbours' edges turn where it runs straight in
/// the plane, so any hinge lays its far end over the neighbour) is cut in two across one of its
/// inner edges, each half hinged onto a neighbour (often different ones: one half onto the
/// floor, the other onto the ceiling; a strip of at most 2,048 triangles): cuts the most even
/// first (at most 48, and each half's
/// 12 longest hinges onto each neighbour that the whole band's motion does not already lay
/// over it),
/// kept where each union is less narrow than the strip and no narrower than its neighbour was
/// (or than `narrow_share`), the cut leaving the least slit. Where no cut places both halves
/// (its neighbours turn twice along it, so each half of any cut turns with them somewhere), it
/// is cut in three: one half placed and the other cut in two
/// again, at most 4 first halves and 4 cuts of each second half tried; and where that fails (its
/// neighbours turn three times, as the wall round a square hole does), in four (at most
/// options.most_band_pieces), the second half
/// cut in three in the same way. A strip none takes is passed
/// over until a join makes a union beside it (new edges to fold over, a neighbour less
/// narrow), then tried again; those left after that stay as they are. Each of those still narrow
/// then grows as join_small_strips grows a crumb (its neighbours' triangles beside it, the one
/// leaving it most compact first, each neighbour keeping at least `min_area` and getting no
/// narrower than it was or than `narrow_share`), until it is narrow over at most `narrow_share`;
/// within 128 triangles, and giving up once 16 taken in a row leave it no less narrow, or it stays
/// as it is. Then label_seams runs on the result.
///
/// \pre as merge_congruent.
/// \throws InvalidInputException as merge_congruent.
std::vector<FlatStrip> join_narrow_strips(std::vector<FlatStrip> strips, double min_width,
                                          double narrow_share, const MergeOptions& options = {},
                                          int most_hinges = 256, double min_area = 0.0);

/// Hinges each flat strip of less than `below_area` onto a neighbour, the smallest first, as
/// join_small_strips hinges a crumb (the hinge that lays it flat leaving the least slit at
/// `min_width`; 0: the first). Fewer pieces to cut: a piece a few square centimetres large folds
/// onto its neighbour, its other shared edges becoming seams of the union with itself. No width
/// check is needed: a disc inside either piece lies inside the union, so the union is narrow
/// over at most the two pieces' narrow areas, a share no larger than the larger of theirs. A
/// union still under `below_area` is tried again; a strip no hinge takes stays. Then
/// label_seams runs.
/// \pre as merge_congruent. \throws InvalidInputException as merge_congruent.
std::vector<FlatStrip> hinge_modest_strips(std::vector<FlatStrip> strips, double below_area,
                                           const MergeOptions& options = {},
                                           double min_width = 0.0);

/// Hands triangles across seams where that makes the pieces cheaper to cut and glue, with a
/// print scale (options.mm_per_unit > 0; otherwise `strips` come back as they are): a triangle
/// of a piece at a sawtooth corner of its outline (count_sawtooth_corners, in page mm) that has
/// an edge on a neighbour's rim goes to that neighbour (with whatever it alone held on,
/// take_triangle) where the neighbour's union with it welds along every edge they share (no
/// slit), lands on none of its triangles, the piece left keeps at least `min_area` and neither
/// gets narrower than `min_width` over more than `narrow_share` of its area (or than it was),
/// and what the two and their seams cost a person drops (MoveCost: the sawtooth corners it
/// straightens against the glue length it adds). The moves that pay are queued by gain, the
/// best applied first; after one, only the two pieces and their neighbours are judged again.
/// The 3D surface is unchanged. Then label_seams runs.
/// \pre as merge_congruent. \throws InvalidInputException as merge_congruent.
std::vector<FlatStrip> smooth_seams(std::vector<FlatStrip> strips, double min_area,
                                    double min_width, double narrow_share,
                                    const MergeOptions& options);

/// The merge node's joins after merge_congruent: join_small_strips, then join_narrow_strips
/// (at most 256 hinges a strip), then join_small_strips once more where crumbs were left, since
/// the narrow joins change their neighbours (a union to fold onto, a neighbour large enough to
/// give triangles), then hinge_modest_strips below options.modest_join_factor times min_area.
/// The ids of the small strips still left go to `left` (when given).
/// \pre as merge_congruent. \throws InvalidInputException as merge_congruent.
std::vector<FlatStrip> join_small_and_narrow_strips(std::vector<FlatStrip> strips, double min_area,
                                                    double min_width,
                                                    const MergeOptions& options = {},
                                                    std::vector<int>* left = nullptr);

}  // namespace papercraft
