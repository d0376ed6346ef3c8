#pragma once
// segment.fuzzy: hierarchical decomposition by fuzzy clustering and minimum cuts, after
// Katz & Tal, "Hierarchical mesh decomposition using fuzzy clustering and cuts", SIGGRAPH 2003,
// with the boundaries then straightened along harmonic iso-lines (smooth curves, as the
// papercraft method prefers: Massarwi, Gotsman, Elber 2007, section 3.1).
//
// Where it departs from Katz & Tal: representatives are chosen on geodesic distances (the
// centre from distance sums to 32 area-spread samples, not all pairs) and not refined
// iteratively; the cut capacity is also proportional to edge length, with the angular average
// taken over the fuzzy region; the hierarchy stops by judging boundaries (necks and concave
// creases stay) instead of by the spread of dihedral angles.

#include <optional>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "engine/refine/refine.h"

namespace papercraft {

/// Settings of a further hierarchy that differ from the main options (unset: the main ones).
struct FuzzyAlternative {
  std::optional<double> angular_weight;
  std::optional<double> convex_eta;
  std::optional<double> fuzzy_epsilon;
};

/// Parses "angular_weight=0.5 fuzzy_epsilon=0.2" (settings separated by spaces).
/// \throws InvalidInputException on an unknown setting or a value that is not a number.
FuzzyAlternative parse_fuzzy_alternative(const std::string& text);

/// The text parse_fuzzy_alternative reads back: "angular_weight=0.5 fuzzy_epsilon=0.2".
std::string format_fuzzy_alternative(const FuzzyAlternative& alternative);

struct FuzzySegmentOptions {
  /// Number of parts of a single (non-hierarchical) k-way decomposition, >= 2; 0 chooses the
  /// number at each level of the hierarchy automatically (Katz & Tal: the largest
  /// drop of the farthest-point distance G(k)). Merging small parts may leave fewer.
  int parts = 0;
  /// Upper bound of the automatic number of parts per level, >= 2.
  int max_parts = 10;
  /// Levels of the hierarchy when parts == 0, >= 1: each part of a level is decomposed again
  /// unless it is smaller than twice the minimum area or at this depth.
  int max_depth = 3;
  /// Weight of the angular term in the dual-graph distance, 1 - delta of Katz & Tal eq. (1);
  /// the geodesic term gets the rest. In [0, 1].
  double angular_weight = 0.8;
  /// eta of Katz & Tal's angular distance eta (1 - cos alpha) for convex edges (concave ones
  /// get 1), so that boundaries prefer concave folds. In (0, 1].
  double convex_eta = 0.1;
  /// A face whose two highest probabilities p1 >= p2 (normalised to p1 + p2 = 1) satisfy
  /// p1 <= 1/2 + fuzzy_epsilon lies in the fuzzy region between the two parts, where the
  /// minimum cut decides. In [0, 0.5).
  double fuzzy_epsilon = 0.1;
  /// With parts == 0, each boundary a decomposition finds is kept only if it is a neck or a
  /// concave crease; the parts beside the weakest other boundary are merged until none is left
  /// (in place of Katz & Tal's stopping rule on the spread of dihedral angles, which a finely
  /// tessellated smooth surface never meets). A neck: the boundary's size squared is at most
  /// neck_ratio times the area of the smaller part beside it, the size being 2 pi times the
  /// boundary's mean distance from its centroid (its length if it is a circle, but blind to the
  /// staircase of mesh edges a cut follows). A sphere's equator scores 2 pi, the waist of the
  /// default dumbbell 0.3, a cylinder of radius r cut into halves of length h 2 pi r / h. > 0.
  double neck_ratio = 2.0;
  /// A concave crease: the surface folds concavely across the boundary by at least this angle
  /// on average over its length (degrees, in [0, 180]).
  double crease_angle_degrees = 20;
  /// Parts smaller than this fraction of the total area are merged into a neighbour; a region
  /// smaller than twice this is not decomposed further. In [0, 1).
  double min_area_fraction = 0.01;
  /// With parts == 0 and a positive value, each level of the hierarchy is judged by its cost:
  /// the refinement (engine/refine/refine.h, with `refine`) is run on the region and on its
  /// parts at this absolute tolerance, and the decomposition
  /// (with or without the boundaries the rule above would drop) that makes the fewest strips
  /// is kept, none unless it makes fewer strips than the region whole. 0 turns this off.
  /// The segment.fuzzy node sets it to the model's tolerance (param strip_estimate).
  double strip_tolerance = 0;
  /// The refinement that judges the levels: the pipeline's own (the segment.fuzzy node passes
  /// the options of the configured select, ruled, hausdorff and cut nodes).
  RefineOptions refine;
  /// The pieces the refinement keeps a person able to cut and glue (the model's limits).
  PieceLimits strip_limits;
  /// With strip_tolerance > 0, also judge the two-way split between each region's farthest
  /// faces (Katz & Tal's two-part decomposition) at every level.
  bool two_way_candidate = true;
  /// With strip_tolerance > 0, also judge each part of a decomposition of three or more
  /// parts split off alone (the rest of the region whole).
  bool single_part_candidates = true;
  /// With strip_tolerance > 0, the whole hierarchy is also built with each of these settings
  /// (the others as above), and of all the decompositions the one that makes the fewest strips
  /// is kept: which settings find a model's parts best differs from model to model (over the
  /// libcgal-demo models at 2%, the defaults and these two each win somewhere). Each costs
  /// about one more hierarchy; empty: the main settings only.
  std::vector<FuzzyAlternative> alternatives = {{0.5, {}, {}}, {{}, {}, 0.2}};
  /// With strip_tolerance > 0, after the hierarchy merge the two adjacent parts (of any
  /// branches) whose union the refinement makes the most strips fewer of, while any pair saves.
  bool merge_neighbours = true;
  /// Replace each boundary by the 1/2 iso-line of a harmonic field between the two sides,
  /// within straighten_width mean edge lengths of it (a smooth curve across the triangles
  /// instead of a staircase of edges). A boundary that runs along a crease (the surface folds
  /// by 30 degrees or more across it on average) is kept where it is.
  bool straighten = true;
  /// Half-width of the band a boundary may move in, in mean edge lengths; > 0.
  double straighten_width = 3.0;
};

/// Decomposes `mesh` into meaningful parts with smooth boundaries. Every face of `mesh` is
/// covered exactly once (straightening splits faces that a boundary crosses; the pieces' areas
/// add up to the face's); neighbouring parts share their boundary vertices (bit-identical
/// coordinates, no T-junctions). Parts carry "v:input_vertex" (the input's property, or the
/// input vertex index if it has none; -1 for vertices inserted on a boundary) and interpolated
/// texture coordinates if `mesh` has them. Each part is connected and a 2-manifold; parts are
/// ordered by their lowest input face. The result does not depend on the number of threads.
/// Costs a few single-source shortest paths on the dual graph per region and level (not Katz
/// & Tal's all pairs), so it suits meshes of up to a few hundred thousand faces.
/// \pre mesh is a triangle mesh without deleted elements.
/// \throws InvalidInputException if mesh has no faces or deleted elements, or an option is out
///   of range.
std::vector<Mesh> segment_fuzzy(const Mesh& mesh, const FuzzySegmentOptions& options = {});

}  // namespace papercraft
