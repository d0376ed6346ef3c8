#include "core/generate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <type_traits>
#include <unordered_map>

#include "core/errors.h"
#include "core/implicit_surface.h"
#include "core/mesh.h"

namespace papercraft {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr long long kMaximumFaces = 20'000'000;

std::string format_number(double value) {
  std::ostringstream stream;
  stream << value;
  return stream.str();
}

[[noreturn]] void fail(const std::string& shape, const std::string& message) {
  throw InvalidInputException(shape + ": " + message);
}

void require_positive(const char* shape, const char* name, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    fail(shape, std::string(name) + " must be a positive finite number (got " +
                    format_number(value) + ")");
  }
}

void require_at_least(const char* shape, const char* name, int value, int minimum) {
  if (value < minimum) {
    fail(shape, std::string(name) + " must be at least " + std::to_string(minimum) + " (got " +
                    std::to_string(value) + ")");
  }
}

void require_face_budget(const char* shape, long long faces) {
  if (faces > kMaximumFaces) {
    fail(shape, "these parameters give " + std::to_string(faces) + " faces; the limit is " +
                    std::to_string(kMaximumFaces));
  }
}

// A grid of vertices point(i, j), i in [0, columns) periodic, j in [0, rows), and quads
// (i,j) (i+1,j) (i+1,j+1) (i,j+1), which are counter-clockwise seen from the side that
// d point/di x d point/dj points to. Optional poles close the first and last rows with fans.
struct GridSurface {
  int columns = 0;
  int rows = 0;
  bool periodic_rows = false;
  std::function<Vec3(int, int)> point;
  std::optional<Vec3> bottom_pole;
  std::optional<Vec3> top_pole;
  std::function<bool(int, int)> keep_quad;
};

void remove_unused_vertices(TriangleMesh& mesh) {
  std::vector<int> new_index(mesh.vertices.size(), -1);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) new_index[v] = 0;
  }
  std::vector<Vec3> kept;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (new_index[v] < 0) continue;
    new_index[v] = static_cast<int>(kept.size());
    kept.push_back(mesh.vertices[v]);
  }
  for (Triangle& t : mesh.triangles) {
    for (int& v : t) v = new_index[v];
  }
  mesh.vertices = std::move(kept);
}

TriangleMesh grid_surface(const GridSurface& grid) {
  TriangleMesh mesh;
  const int n = grid.columns;
  auto index = [&](int i, int j) { return (j % grid.rows) * n + (i % n); };
  mesh.vertices.reserve(static_cast<std::size_t>(n) * grid.rows + 2);
  for (int j = 0; j < grid.rows; ++j) {
    for (int i = 0; i < n; ++i) mesh.vertices.push_back(grid.point(i, j));
  }
  const int bands = grid.periodic_rows ? grid.rows : grid.rows - 1;
  for (int j = 0; j < bands; ++j) {
    for (int i = 0; i < n; ++i) {
      if (grid.keep_quad && !grid.keep_quad(i, j)) continue;
      const int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  }
  if (grid.bottom_pole) {
    const int pole = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(*grid.bottom_pole);
    for (int i = 0; i < n; ++i) mesh.triangles.push_back({pole, index(i + 1, 0), index(i, 0)});
  }
  if (grid.top_pole) {
    const int pole = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(*grid.top_pole);
    const int last = grid.rows - 1;
    for (int i = 0; i < n; ++i)
      mesh.triangles.push_back({index(i, last), index(i + 1, last), pole});
  }
  if (grid.keep_quad) remove_unused_vertices(mesh);
  return mesh;
}

double angle(int i, int segments) {
  return 2.0 * kPi * i / segments;
}

// Surface of revolution about z of the profile points (r, z), r > 0, ordered from bottom to
// top, so that the normal (dz/ds cos, dz/ds sin, -dr/ds) points outward.
TriangleMesh revolve(const std::vector<Vec2>& profile, int segments,
                     std::optional<double> bottom_pole_z, std::optional<double> top_pole_z) {
  GridSurface grid;
  grid.columns = segments;
  grid.rows = static_cast<int>(profile.size());
  grid.point = [&](int i, int j) {
    const double theta = angle(i, segments);
    return Vec3(profile[j].x() * std::cos(theta), profile[j].x() * std::sin(theta), profile[j].y());
  };
  if (bottom_pole_z) grid.bottom_pole = Vec3(0.0, 0.0, *bottom_pole_z);
  if (top_pole_z) grid.top_pole = Vec3(0.0, 0.0, *top_pole_z);
  return grid_surface(grid);
}

void check_tube(const char* shape, double height, int segments, int rings) {
  require_positive(shape, "height", height);
  require_at_least(shape, "segments", segments, 3);
  require_at_least(shape, "rings", rings, 1);
  require_face_budget(shape, 2LL * segments * rings);
}

std::vector<Vec2> straight_profile(double bottom_radius, double top_radius, double height,
                                   int rings) {
  std::vector<Vec2> profile;
  for (int j = 0; j <= rings; ++j) {
    const double s = static_cast<double>(j) / rings;
    profile.emplace_back((1.0 - s) * bottom_radius + s * top_radius, (s - 0.5) * height);
  }
  return profile;
}

// ---------------------------------------------------------------------------------------
// The field of figure_eight (two blended tori), polygonised by implicit_surface.h.

double torus_distance(const Vec3& p, double center_x, double major_radius, double minor_radius) {
  const double q = std::hypot(p.x() - center_x, p.y()) - major_radius;
  return std::hypot(q, p.z()) - minor_radius;
}

// Quadratic smooth minimum (Quilez); its gradient is a convex combination of those of a and
// b, so the union of two distance functions stays 1-Lipschitz.
double smooth_minimum(double a, double b, double k) {
  if (k <= 0.0) return std::min(a, b);
  const double h = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
  return b + (a - b) * h - k * h * (1.0 - h);
}

// ---------------------------------------------------------------------------------------
// Pawn profile: pieces of curve from the bottom pole to the top pole, in units of the height.

struct ProfilePiece {
  std::function<Vec2(double)> curve;  // s in [0, 1] -> (r, z)
  double length = 0.0;
};

ProfilePiece line_piece(Vec2 from, Vec2 to) {
  return {[from, to](double s) { return Vec2((1.0 - s) * from + s * to); }, (to - from).norm()};
}

ProfilePiece measured_piece(std::function<Vec2(double)> curve) {
  double length = 0.0;
  constexpr int kSteps = 256;
  for (int k = 0; k < kSteps; ++k) {
    length += (curve((k + 1.0) / kSteps) - curve(static_cast<double>(k) / kSteps)).norm();
  }
  return {std::move(curve), length};
}

std::vector<ProfilePiece> pawn_profile() {
  const double head_center = 0.80, head_radius = 0.17, neck_radius = 0.10;
  const double head_start = std::asin(neck_radius / head_radius);
  const Vec2 neck(neck_radius, head_center - head_radius * std::cos(head_start));
  std::vector<ProfilePiece> pieces;
  pieces.push_back(line_piece(Vec2(0.0, 0.0), Vec2(0.36, 0.0)));    // bottom disc
  pieces.push_back(line_piece(Vec2(0.36, 0.0), Vec2(0.36, 0.05)));  // base rim
  pieces.push_back(measured_piece([](double s) {                    // rounded base shoulder
    const double phi = 0.5 * kPi * s;
    return Vec2(0.22 + 0.14 * std::cos(phi), 0.05 + 0.09 * std::sin(phi));
  }));
  pieces.push_back(measured_piece([](double s) {  // body, flaring towards the base
    return Vec2(0.11 + 0.11 * (1.0 - s) * (1.0 - s), 0.14 + 0.42 * s);
  }));
  pieces.push_back(line_piece(Vec2(0.11, 0.56), Vec2(0.20, 0.58)));  // collar underside
  pieces.push_back(measured_piece([](double s) {                     // collar rim
    const double phi = kPi * (s - 0.5);
    return Vec2(0.20 + 0.02 * std::cos(phi), 0.60 + 0.02 * std::sin(phi));
  }));
  pieces.push_back(line_piece(Vec2(0.20, 0.62), neck));  // collar top
  pieces.push_back(measured_piece([=](double s) {        // head ball up to the top pole
    const double alpha = head_start + (kPi - head_start) * s;
    return Vec2(head_radius * std::sin(alpha), head_center - head_radius * std::cos(alpha));
  }));
  return pieces;
}

// `samples` points strictly between the two poles: every piece keeps its end points (the
// profile's corners) and gets a number of intervals proportional to its length.
std::vector<Vec2> sample_profile(const std::vector<ProfilePiece>& pieces, int samples) {
  const int intervals = samples + 1;
  const int count = static_cast<int>(pieces.size());
  double total = 0.0;
  for (const ProfilePiece& piece : pieces) total += piece.length;
  std::vector<int> per_piece(count, 1);
  std::vector<double> remainder(count);
  int assigned = count;
  for (int p = 0; p < count; ++p) {
    const double share = pieces[p].length / total * (intervals - count);
    per_piece[p] += static_cast<int>(std::floor(share));
    remainder[p] = share - std::floor(share);
    assigned += static_cast<int>(std::floor(share));
  }
  std::vector<int> order(count);
  for (int p = 0; p < count; ++p) order[p] = p;
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return remainder[a] > remainder[b]; });
  for (int k = 0; assigned < intervals; ++k, ++assigned) ++per_piece[order[k % count]];

  std::vector<Vec2> points;
  for (int p = 0; p < count; ++p) {
    for (int k = (p == 0 ? 1 : 0); k < per_piece[p]; ++k) {
      points.push_back(pieces[p].curve(static_cast<double>(k) / per_piece[p]));
    }
  }
  return points;
}

}  // namespace

TriangleMesh open_cylinder(const OpenCylinderOptions& options) {
  const char* shape = "open_cylinder";
  require_positive(shape, "radius", options.radius);
  check_tube(shape, options.height, options.segments, options.rings);
  return revolve(straight_profile(options.radius, options.radius, options.height, options.rings),
                 options.segments, std::nullopt, std::nullopt);
}

TriangleMesh elliptic_cylinder(const EllipticCylinderOptions& options) {
  const char* shape = "elliptic_cylinder";
  require_positive(shape, "semi_axis_x", options.semi_axis_x);
  require_positive(shape, "semi_axis_y", options.semi_axis_y);
  check_tube(shape, options.height, options.segments, options.rings);
  GridSurface grid;
  grid.columns = options.segments;
  grid.rows = options.rings + 1;
  grid.point = [&](int i, int j) {
    const double theta = angle(i, options.segments);
    return Vec3(options.semi_axis_x * std::cos(theta), options.semi_axis_y * std::sin(theta),
                (static_cast<double>(j) / options.rings - 0.5) * options.height);
  };
  return grid_surface(grid);
}

TriangleMesh cone_frustum(const ConeFrustumOptions& options) {
  const char* shape = "cone_frustum";
  require_positive(shape, "bottom_radius", options.bottom_radius);
  require_positive(shape, "top_radius", options.top_radius);
  check_tube(shape, options.height, options.segments, options.rings);
  return revolve(
      straight_profile(options.bottom_radius, options.top_radius, options.height, options.rings),
      options.segments, std::nullopt, std::nullopt);
}

TriangleMesh sphere(const SphereOptions& options) {
  const char* shape = "sphere";
  require_positive(shape, "radius", options.radius);
  require_at_least(shape, "subdivisions", options.subdivisions, 0);
  if (options.subdivisions > 8) {
    fail(shape,
         "subdivisions must be at most 8 (got " + std::to_string(options.subdivisions) + ")");
  }
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh mesh;
  mesh.vertices = {Vec3(-1, g, 0), Vec3(1, g, 0), Vec3(-1, -g, 0), Vec3(1, -g, 0),
                   Vec3(0, -1, g), Vec3(0, 1, g), Vec3(0, -1, -g), Vec3(0, 1, -g),
                   Vec3(g, 0, -1), Vec3(g, 0, 1), Vec3(-g, 0, -1), Vec3(-g, 0, 1)};
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (Vec3& v : mesh.vertices) v.normalize();
  for (int level = 0; level < options.subdivisions; ++level) {
    std::unordered_map<std::int64_t, int> midpoint;
    auto middle = [&](int a, int b) {
      const std::int64_t key = static_cast<std::int64_t>(std::min(a, b)) << 32 |
                               static_cast<std::int64_t>(std::max(a, b));
      auto [it, inserted] = midpoint.try_emplace(key, static_cast<int>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]).normalized());
      return it->second;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) {
      const int ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(finer);
  }
  for (Vec3& v : mesh.vertices) v *= options.radius;
  return mesh;
}

TriangleMesh torus(const TorusOptions& options) {
  const char* shape = "torus";
  require_positive(shape, "major_radius", options.major_radius);
  require_positive(shape, "minor_radius", options.minor_radius);
  if (options.minor_radius >= options.major_radius) {
    fail(shape, "minor_radius (" + format_number(options.minor_radius) +
                    ") must be smaller than major_radius (" + format_number(options.major_radius) +
                    ")");
  }
  require_at_least(shape, "segments", options.segments, 3);
  require_at_least(shape, "tube_segments", options.tube_segments, 3);
  require_face_budget(shape, 2LL * options.segments * options.tube_segments);
  GridSurface grid;
  grid.columns = options.segments;
  grid.rows = options.tube_segments;
  grid.periodic_rows = true;
  grid.point = [&](int i, int j) {
    const double u = angle(i, options.segments), v = angle(j, options.tube_segments);
    const double r = options.major_radius + options.minor_radius * std::cos(v);
    return Vec3(r * std::cos(u), r * std::sin(u), options.minor_radius * std::sin(v));
  };
  return grid_surface(grid);
}

TriangleMesh figure_eight(const FigureEightOptions& options) {
  const char* shape = "figure_eight";
  require_positive(shape, "major_radius", options.major_radius);
  require_positive(shape, "minor_radius", options.minor_radius);
  if (options.minor_radius > 0.5 * options.major_radius) {
    fail(shape, "minor_radius (" + format_number(options.minor_radius) +
                    ") must be at most major_radius / 2 (" +
                    format_number(0.5 * options.major_radius) + ")");
  }
  if (!std::isfinite(options.blend) || options.blend < 0.0 ||
      options.blend > options.minor_radius) {
    fail(shape, "blend must be in [0, minor_radius = " + format_number(options.minor_radius) +
                    "] (got " + format_number(options.blend) + ")");
  }
  const double major = options.major_radius, minor = options.minor_radius;
  const double center = major + 0.5 * minor;
  const double length = 2.0 * (center + major + minor);
  const int minimum_resolution = static_cast<int>(std::ceil(2.0 * length / minor - 1e-9));
  if (options.resolution < minimum_resolution) {
    fail(shape, "resolution " + std::to_string(options.resolution) +
                    " is too coarse to resolve the tube; use at least " +
                    std::to_string(minimum_resolution));
  }
  if (options.resolution > 1000) {
    fail(shape, "resolution must be at most 1000 (got " + std::to_string(options.resolution) + ")");
  }

  const auto field = [=](const Vec3& p) {
    return smooth_minimum(torus_distance(p, -center, major, minor),
                          torus_distance(p, center, major, minor), options.blend);
  };
  ImplicitGrid grid;
  grid.cell = length / options.resolution;
  // Two cells of margin beyond the shape (which the blend can widen by blend / 4).
  const double margin = 0.25 * options.blend + 2.0 * grid.cell;
  const Vec3 half(center + major + minor + margin, major + minor + margin, minor + margin);
  for (int axis = 0; axis < 3; ++axis) {
    const int cells = static_cast<int>(std::ceil(2.0 * half[axis] / grid.cell));
    grid.nodes[axis] = cells + 1;
    grid.origin[axis] = -0.5 * cells * grid.cell;
  }
  const double push = 0.1 * grid.cell;
  grid.values.resize(static_cast<std::size_t>(grid.nodes[0]) * grid.nodes[1] * grid.nodes[2]);
  for (int z = 0; z < grid.nodes[2]; ++z) {
    for (int y = 0; y < grid.nodes[1]; ++y) {
      for (int x = 0; x < grid.nodes[0]; ++x) {
        const Vec3 p = grid.position(x, y, z);
        double value = field(p);
        // Keeps every crossing at least push / (sqrt(3) cell) from a node: no slivers.
        if (std::abs(value) < push) value = value < 0.0 ? -push : push;
        grid.values[grid.node_index(x, y, z)] = value;
      }
    }
  }
  return remesh_implicit_surface(marching_tetrahedra(grid), field, grid.cell, 3);
}

TriangleMesh pawn(const PawnOptions& options) {
  const char* shape = "pawn";
  require_positive(shape, "height", options.height);
  require_at_least(shape, "segments", options.segments, 3);
  const std::vector<ProfilePiece> pieces = pawn_profile();
  require_at_least(shape, "profile_samples", options.profile_samples,
                   static_cast<int>(pieces.size()) - 1);
  require_face_budget(shape, 2LL * options.segments * options.profile_samples);
  std::vector<Vec2> profile = sample_profile(pieces, options.profile_samples);
  for (Vec2& point : profile) point *= options.height;
  const Vec2 top = pieces.back().curve(1.0);
  return revolve(profile, options.segments, 0.0, top.y() * options.height);
}

TriangleMesh cylinder_two_holes(const CylinderTwoHolesOptions& options) {
  const char* shape = "cylinder_two_holes";
  require_positive(shape, "radius", options.radius);
  require_positive(shape, "height", options.height);
  require_at_least(shape, "segments", options.segments, 6);
  require_at_least(shape, "rings", options.rings, 3);
  require_at_least(shape, "hole_segments", options.hole_segments, 1);
  require_at_least(shape, "hole_rings", options.hole_rings, 1);
  // At least one quad between the holes and between a hole and a rim keeps the 4 loops apart.
  if (options.hole_segments > options.segments / 2 - 1) {
    fail(shape, "hole_segments must be at most segments / 2 - 1 = " +
                    std::to_string(options.segments / 2 - 1) + " (got " +
                    std::to_string(options.hole_segments) + ")");
  }
  if (options.hole_rings > options.rings - 2) {
    fail(shape, "hole_rings must be at most rings - 2 = " + std::to_string(options.rings - 2) +
                    " (got " + std::to_string(options.hole_rings) + ")");
  }
  require_face_budget(shape, 2LL * options.segments * options.rings);
  const std::vector<Vec2> profile =
      straight_profile(options.radius, options.radius, options.height, options.rings);
  GridSurface grid;
  grid.columns = options.segments;
  grid.rows = options.rings + 1;
  grid.point = [&](int i, int j) {
    const double theta = angle(i, options.segments);
    return Vec3(options.radius * std::cos(theta), options.radius * std::sin(theta), profile[j].y());
  };
  const int first_ring = (options.rings - options.hole_rings) / 2;
  const int second_start = options.segments / 2;
  grid.keep_quad = [&](int i, int j) {
    if (j < first_ring || j >= first_ring + options.hole_rings) return true;
    const bool in_first = i < options.hole_segments;
    const bool in_second = i >= second_start && i < second_start + options.hole_segments;
    return !in_first && !in_second;
  };
  return grid_surface(grid);
}

TriangleMesh box(const BoxOptions& options) {
  const char* shape = "box";
  const std::array<double, 3> size = {options.size_x, options.size_y, options.size_z};
  const std::array<int, 3> divisions = {options.divisions_x, options.divisions_y,
                                        options.divisions_z};
  const std::array<const char*, 3> size_names = {"size_x", "size_y", "size_z"};
  const std::array<const char*, 3> division_names = {"divisions_x", "divisions_y", "divisions_z"};
  for (int axis = 0; axis < 3; ++axis) {
    require_positive(shape, size_names[axis], size[axis]);
    require_at_least(shape, division_names[axis], divisions[axis], 1);
  }
  const long long nx = divisions[0], ny = divisions[1], nz = divisions[2];
  require_face_budget(shape, 4 * (nx * ny + ny * nz + nz * nx));

  TriangleMesh mesh;
  std::unordered_map<std::int64_t, int> lattice_vertex;
  auto vertex = [&](const std::array<int, 3>& lattice) {
    const std::int64_t key =
        (static_cast<std::int64_t>(lattice[2]) * (ny + 1) + lattice[1]) * (nx + 1) + lattice[0];
    auto [it, inserted] = lattice_vertex.try_emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) {
      Vec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        p[axis] = (static_cast<double>(lattice[axis]) / divisions[axis] - 0.5) * size[axis];
      }
      mesh.vertices.push_back(p);
    }
    return it->second;
  };
  // Face normal axis and side; (u, v) chosen so that e_u x e_v is the outward normal.
  for (int normal = 0; normal < 3; ++normal) {
    for (int side = 0; side < 2; ++side) {
      int u = (normal + 1) % 3, v = (normal + 2) % 3;
      if (side == 0) std::swap(u, v);
      for (int b = 0; b < divisions[v]; ++b) {
        for (int a = 0; a < divisions[u]; ++a) {
          auto corner = [&](int du, int dv) {
            std::array<int, 3> lattice{};
            lattice[normal] = side == 0 ? 0 : divisions[normal];
            lattice[u] = a + du;
            lattice[v] = b + dv;
            return vertex(lattice);
          };
          const int p00 = corner(0, 0), p10 = corner(1, 0), p11 = corner(1, 1), p01 = corner(0, 1);
          mesh.triangles.push_back({p00, p10, p11});
          mesh.triangles.push_back({p00, p11, p01});
        }
      }
    }
  }
  return mesh;
}

TriangleMesh capped_cylinder(const CappedCylinderOptions& options) {
  const char* shape = "capped_cylinder";
  require_positive(shape, "radius", options.radius);
  check_tube(shape, options.height, options.segments, options.rings);
  require_at_least(shape, "cap_rings", options.cap_rings, 1);
  const long long circles = options.rings + 2LL * options.cap_rings - 1;
  require_face_budget(shape, 2LL * options.segments * circles);
  const double r = options.radius, half = 0.5 * options.height;
  std::vector<Vec2> profile;
  for (int k = 1; k <= options.cap_rings; ++k) {
    profile.emplace_back(r * k / options.cap_rings, -half);
  }
  for (int j = 1; j < options.rings; ++j) {
    profile.emplace_back(r, (static_cast<double>(j) / options.rings - 0.5) * options.height);
  }
  for (int k = options.cap_rings; k >= 1; --k)
    profile.emplace_back(r * k / options.cap_rings, half);
  return revolve(profile, options.segments, -half, half);
}

TriangleMesh dumbbell(const DumbbellOptions& options) {
  const char* shape = "dumbbell";
  require_positive(shape, "sphere_radius", options.sphere_radius);
  require_positive(shape, "handle_radius", options.handle_radius);
  require_positive(shape, "handle_length", options.handle_length);
  if (options.handle_radius >= options.sphere_radius) {
    fail(shape, "handle_radius (" + format_number(options.handle_radius) +
                    ") must be smaller than sphere_radius (" +
                    format_number(options.sphere_radius) + ")");
  }
  require_at_least(shape, "segments", options.segments, 3);
  require_at_least(shape, "sphere_rings", options.sphere_rings, 2);
  require_at_least(shape, "handle_rings", options.handle_rings, 1);
  const long long circles = 2LL * options.sphere_rings + options.handle_rings - 1;
  require_face_budget(shape, 2LL * options.segments * circles);

  const double radius = options.sphere_radius, bar = options.handle_radius;
  const double half_length = 0.5 * options.handle_length;
  const double bottom_center = -half_length - std::sqrt(radius * radius - bar * bar);
  // Angle from the south pole of the bottom sphere to the circle where the bar starts.
  const double junction = kPi - std::asin(bar / radius);
  std::vector<Vec2> bottom;
  for (int k = 1; k <= options.sphere_rings; ++k) {
    const double alpha = junction * k / options.sphere_rings;
    bottom.emplace_back(radius * std::sin(alpha), bottom_center - radius * std::cos(alpha));
  }
  bottom.back() = Vec2(bar, -half_length);
  std::vector<Vec2> profile = bottom;
  for (int l = 1; l < options.handle_rings; ++l) {
    profile.emplace_back(bar, -half_length + options.handle_length * l / options.handle_rings);
  }
  for (auto it = bottom.rbegin(); it != bottom.rend(); ++it) {
    profile.emplace_back(it->x(), -it->y());
  }
  const double pole = bottom_center - radius;
  return revolve(profile, options.segments, pole, -pole);
}

}  // namespace papercraft
