#pragma once
// Analytic test meshes: parametric and implicit shapes with known topology (Euler
// characteristic, boundary loops) and, where there is one, known vertex and face counts.
// Used by the tests and benchmarks and by `papercraft generate SHAPE OUT --param k=v`.
//
// Every generator returns a TriangleMesh that is a connected, consistently oriented
// 2-manifold (counter-clockwise seen from outside, so closed shapes have outward normals
// and positive signed volume), without unused or duplicate vertices and without
// zero-area triangles. Shapes are centred on the origin; axes of revolution are the z axis.
// Every generator throws InvalidInputException naming the shape and the parameter when a
// length is not a positive finite number, a count is below its minimum, or the mesh would
// exceed 20 million faces.

#include <map>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

struct OpenCylinderOptions {
  double radius = 1.0;
  double height = 2.0;
  int segments = 32;  ///< vertices around each circle, >= 3
  int rings = 8;      ///< bands of quads along the axis (rings + 1 circles), >= 1
};

/// Cylinder without caps, z in [-height/2, height/2]; 2 boundary loops, Euler characteristic 0.
/// #V = segments * (rings + 1), #F = 2 * segments * rings.
TriangleMesh open_cylinder(const OpenCylinderOptions& options = {});

struct EllipticCylinderOptions {
  double semi_axis_x = 1.5;
  double semi_axis_y = 0.75;
  double height = 2.0;
  int segments = 32;  ///< >= 3, equally spaced in the parameter angle
  int rings = 8;      ///< >= 1
};

/// Open cylinder over the ellipse (x/semi_axis_x)^2 + (y/semi_axis_y)^2 = 1; 2 boundary loops.
/// #V = segments * (rings + 1), #F = 2 * segments * rings.
TriangleMesh elliptic_cylinder(const EllipticCylinderOptions& options = {});

struct ConeFrustumOptions {
  double bottom_radius = 1.0;  ///< at z = -height/2
  double top_radius = 0.5;     ///< at z = +height/2; > 0 (a pointed cone is not a frustum)
  double height = 2.0;
  int segments = 32;  ///< >= 3
  int rings = 8;      ///< >= 1
};

/// Open truncated cone; 2 boundary loops. #V = segments * (rings + 1), #F = 2 * segments * rings.
TriangleMesh cone_frustum(const ConeFrustumOptions& options = {});

struct SphereOptions {
  double radius = 1.0;
  int subdivisions = 3;  ///< loop subdivisions of the icosahedron, 0..8
};

/// Icosphere (vertices on the sphere); closed, Euler characteristic 2.
/// #V = 10 * 4^subdivisions + 2, #F = 20 * 4^subdivisions.
TriangleMesh sphere(const SphereOptions& options = {});

struct TorusOptions {
  double major_radius = 1.0;   ///< distance from the z axis to the tube centre
  double minor_radius = 0.35;  ///< tube radius, < major_radius
  int segments = 48;           ///< around the z axis, >= 3
  int tube_segments = 24;      ///< around the tube, >= 3
};

/// Torus around the z axis; closed, genus 1 (Euler characteristic 0).
/// #V = segments * tube_segments, #F = 2 * segments * tube_segments.
TriangleMesh torus(const TorusOptions& options = {});

struct FigureEightOptions {
  double major_radius = 1.0;   ///< of each torus
  double minor_radius = 0.35;  ///< of each torus, <= major_radius / 2
  double blend = 0.2;          ///< smooth-union radius at the junction, in [0, minor_radius]
  int resolution = 30;         ///< grid cells along x; cell size must be <= minor_radius / 2
};

/// Closed genus-2 surface ("double torus"): the zero set of the smooth union of two torus
/// distance functions centred at x = +-(major_radius + minor_radius / 2), Euler
/// characteristic -2. Polygonised by marching tetrahedra on a regular grid (each cube split
/// into 6 Kuhn tetrahedra): the zero set of the piecewise-linear interpolant, hence a closed
/// 2-manifold; grid values within 0.1 cell of zero are pushed to +-0.1 cell so no crossing
/// sits on a grid node. Then remeshed towards edge length = cell size (Botsch & Kobbelt
/// without splits: collapses under the link condition, angle-improving flips, tangential
/// relaxation with projection onto the zero set), which keeps manifoldness and genus and
/// gives smallest angles of about 30 degrees. No closed-form counts; the face count grows as
/// resolution^2 (about 2400 faces by default, 2200 at the minimum resolution).
/// Throws InvalidInputException if the grid is too coarse to resolve the tube (cell size
/// > minor_radius / 2; the message gives the minimum resolution) or resolution > 1000.
TriangleMesh figure_eight(const FigureEightOptions& options = {});

struct PawnOptions {
  double height = 2.0;
  int segments = 32;         ///< around the z axis, >= 3
  int profile_samples = 40;  ///< profile points between the two poles, >= 7
};

/// Chess pawn: surface of revolution of a profile with base, body, collar and head ball,
/// z in [0, height]; poles closed by triangle fans. Closed, Euler characteristic 2.
/// #V = segments * profile_samples + 2, #F = 2 * segments * profile_samples.
TriangleMesh pawn(const PawnOptions& options = {});

struct CylinderTwoHolesOptions {
  double radius = 1.0;
  double height = 2.0;
  int segments = 32;      ///< >= 6
  int rings = 12;         ///< >= 3
  int hole_segments = 6;  ///< quads removed around the axis per hole, 1..segments/2 - 1
  int hole_rings = 4;     ///< quads removed along the axis per hole, 1..rings - 2
};

/// Open cylinder (as open_cylinder) with two disjoint rectangular holes of
/// hole_segments x hole_rings quads, centred along the axis and on opposite sides
/// (starting at angle 0 and at segment segments/2). 4 boundary loops, Euler characteristic -2.
/// #V = segments * (rings + 1) - 2 * (hole_segments - 1) * (hole_rings - 1),
/// #F = 2 * segments * rings - 4 * hole_segments * hole_rings.
TriangleMesh cylinder_two_holes(const CylinderTwoHolesOptions& options = {});

struct BoxOptions {
  double size_x = 2.0;
  double size_y = 1.5;
  double size_z = 1.0;
  int divisions_x = 8;  ///< grid cells along x on the faces that contain x, >= 1
  int divisions_y = 6;
  int divisions_z = 4;
};

/// Closed box [-size/2, size/2]^3 with every face a grid of quads (split into triangles),
/// sharp creases along its 12 edges. Euler characteristic 2. With n = divisions:
/// #V = (nx+1)(ny+1)(nz+1) - (nx-1)(ny-1)(nz-1), #F = 4 (nx ny + ny nz + nz nx).
TriangleMesh box(const BoxOptions& options = {});

struct CappedCylinderOptions {
  double radius = 1.0;
  double height = 2.0;
  int segments = 32;  ///< >= 3
  int rings = 8;      ///< bands of quads along the side, >= 1
  int cap_rings = 4;  ///< concentric bands on each disc (the innermost a fan), >= 1
};

/// Cylinder closed by two flat discs, creases at the two rims; closed, Euler characteristic 2.
/// With m = rings + 2 * cap_rings - 1 circles of vertices:
/// #V = segments * m + 2, #F = 2 * segments * m.
TriangleMesh capped_cylinder(const CappedCylinderOptions& options = {});

struct DumbbellOptions {
  double sphere_radius = 1.0;
  double handle_radius = 0.3;  ///< < sphere_radius
  double handle_length = 1.5;  ///< length of the bar visible between the two spheres
  int segments = 32;           ///< >= 3
  int sphere_rings = 12;       ///< profile bands on each sphere, >= 2
  int handle_rings = 6;        ///< profile bands along the bar, >= 1
};

/// Two spheres on the z axis joined by a cylindrical bar: a closed surface of revolution,
/// genus 0 (Euler characteristic 2), concave creases where bar meets sphere.
/// With m = 2 * sphere_rings + handle_rings - 1 circles of vertices:
/// #V = segments * m + 2, #F = 2 * segments * m.
TriangleMesh dumbbell(const DumbbellOptions& options = {});

/// A parameter of a shape for the command line's help; integer parameters (counts) have
/// integral defaults and reject non-integral values.
struct ShapeParameter {
  std::string name;
  double default_value;
  std::string description;
};

/// Names accepted by generate_shape, in the order of this header.
std::vector<std::string> shape_names();

/// One-line description of a shape. Throws InvalidInputException for an unknown name.
std::string shape_description(const std::string& name);

/// The parameters of a shape (the fields of its Options struct, same names and defaults).
/// Throws InvalidInputException for an unknown name (the message lists the known shapes).
std::vector<ShapeParameter> shape_parameters(const std::string& name);

/// Generate a shape by name; parameters not given keep their defaults.
/// Throws InvalidInputException for an unknown shape (listing the known ones), an unknown
/// parameter (listing the shape's parameters), a non-integral value for a count, or a value
/// that violates the shape's preconditions.
TriangleMesh generate_shape(const std::string& name,
                            const std::map<std::string, double>& parameters = {});

}  // namespace papercraft
