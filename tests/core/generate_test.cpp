#include "core/generate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/mesh.h"

namespace papercraft {
namespace {

constexpr double kPi = std::numbers::pi;

double signed_volume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (const Triangle& t : mesh.triangles) {
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
  }
  return volume;
}

Vec3 triangle_normal(const TriangleMesh& mesh, const Triangle& t) {
  return (mesh.vertices[t[1]] - mesh.vertices[t[0]])
      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
}

Vec3 centroid(const TriangleMesh& mesh, const Triangle& t) {
  return (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
}

double bounding_diagonal(const TriangleMesh& mesh) {
  const auto [lo, hi] = bounding_box(mesh.vertices);
  return (hi - lo).norm();
}

// Smallest interior angle over all triangles, in degrees.
double minimum_angle_degrees(const TriangleMesh& mesh) {
  double smallest = 180.0;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.vertices[t[(k + 1) % 3]] - mesh.vertices[t[k]];
      const Vec3 b = mesh.vertices[t[(k + 2) % 3]] - mesh.vertices[t[k]];
      smallest = std::min(smallest, std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / kPi);
    }
  }
  return smallest;
}

// Edges whose two faces' normals differ by more than 60 degrees.
int sharp_edge_count(const TriangleMesh& input) {
  Mesh mesh = to_mesh(input);
  mesh.request_face_normals();
  mesh.update_face_normals();
  int count = 0;
  for (auto e : mesh.edges()) {
    if (e.is_boundary()) continue;
    const auto n0 = mesh.normal(e.h0().face()), n1 = mesh.normal(e.h1().face());
    if (OpenMesh::dot(n0, n1) < 0.5) ++count;
  }
  return count;
}

// The invariants every generator promises: valid indices, no unused or duplicate vertices,
// no zero-area triangle, each directed edge used once (consistent orientation), edges
// shared by at most two faces, one fan per vertex, connected, the given Euler
// characteristic and number of boundary loops; closed meshes enclose positive volume.
void expect_valid_surface(const TriangleMesh& mesh, int euler, int loops) {
  ASSERT_FALSE(mesh.empty());
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<int> faces_at(n, 0);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, n);
      ++faces_at[v];
    }
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
  }
  for (int v = 0; v < n; ++v) ASSERT_GT(faces_at[v], 0) << "vertex " << v << " is unused";

  const double scale = bounding_diagonal(mesh);
  double closest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      closest = std::min(closest, (mesh.vertices[a] - mesh.vertices[b]).squaredNorm());
    }
  }
  EXPECT_GT(std::sqrt(closest), 1e-6 * scale) << "duplicate vertices";
  double smallest_area = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles) {
    smallest_area = std::min(smallest_area, 0.5 * triangle_normal(mesh, t).norm());
  }
  EXPECT_GT(smallest_area, 1e-8 * scale * scale) << "degenerate triangle";

  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  int unpaired = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "directed edge " << edge.first << "-" << edge.second;
    if (!directed.count({edge.second, edge.first})) ++unpaired;
  }

  Mesh converted;
  ASSERT_NO_THROW(converted = to_mesh(mesh));
  for (auto v : converted.vertices()) {
    int around = 0;
    for (auto f : converted.vf_range(v)) {
      (void)f;
      ++around;
    }
    EXPECT_EQ(around, faces_at[v.idx()]) << "vertex " << v.idx() << " has more than one fan";
  }
  EXPECT_EQ(euler_characteristic(converted), euler);
  EXPECT_EQ(boundary_loops(converted).size(), static_cast<std::size_t>(loops));
  EXPECT_EQ(connected_components(converted), 1);
  if (loops == 0) {
    EXPECT_EQ(unpaired, 0);
    EXPECT_GT(signed_volume(mesh), 0.0);
  }
}

// For open surfaces around the z axis: every face normal points away from the axis, measured
// with the gradient of (x/a)^2 + (y/b)^2.
void expect_normals_away_from_axis(const TriangleMesh& mesh, double a = 1.0, double b = 1.0) {
  int inward = 0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 c = centroid(mesh, t);
    const Vec3 gradient(c.x() / (a * a), c.y() / (b * b), 0.0);
    if (triangle_normal(mesh, t).dot(gradient) <= 0.0) ++inward;
  }
  EXPECT_EQ(inward, 0);
}

TEST(Generate, OpenCylinderCountsTopologyAndGeometry) {
  const TriangleMesh mesh = open_cylinder();
  EXPECT_EQ(mesh.vertices.size(), 32u * 9u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 32u * 8u);
  expect_valid_surface(mesh, 0, 2);
  expect_normals_away_from_axis(mesh);
  for (const Vec3& p : mesh.vertices) {
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0, 1e-12);
    EXPECT_LE(std::abs(p.z()), 1.0 + 1e-12);
  }
  const auto loops = boundary_loops(to_mesh(mesh));
  EXPECT_EQ(loops[0].size(), 32u);
  EXPECT_EQ(loops[1].size(), 32u);

  const TriangleMesh small =
      open_cylinder({.radius = 2.0, .height = 1.0, .segments = 5, .rings = 3});
  EXPECT_EQ(small.vertices.size(), 20u);
  EXPECT_EQ(small.triangles.size(), 30u);
  expect_valid_surface(small, 0, 2);
  const auto [lo, hi] = bounding_box(small.vertices);
  EXPECT_NEAR(hi.z() - lo.z(), 1.0, 1e-12);
  EXPECT_NEAR(hi.x(), 2.0, 1e-12);
}

TEST(Generate, EllipticCylinderLiesOnEllipse) {
  const EllipticCylinderOptions options{
      .semi_axis_x = 2.0, .semi_axis_y = 0.5, .segments = 7, .rings = 2};
  const TriangleMesh mesh = elliptic_cylinder(options);
  EXPECT_EQ(mesh.vertices.size(), 21u);
  EXPECT_EQ(mesh.triangles.size(), 28u);
  expect_valid_surface(mesh, 0, 2);
  expect_normals_away_from_axis(mesh, 2.0, 0.5);
  for (const Vec3& p : mesh.vertices) {
    EXPECT_NEAR(std::pow(p.x() / 2.0, 2) + std::pow(p.y() / 0.5, 2), 1.0, 1e-12);
  }
  const TriangleMesh standard = elliptic_cylinder();
  EXPECT_EQ(standard.triangles.size(), 512u);
  expect_valid_surface(standard, 0, 2);
}

TEST(Generate, ConeFrustumRadiiAndOrientation) {
  const TriangleMesh mesh = cone_frustum(
      {.bottom_radius = 1.0, .top_radius = 0.25, .height = 3.0, .segments = 6, .rings = 4});
  EXPECT_EQ(mesh.vertices.size(), 30u);
  EXPECT_EQ(mesh.triangles.size(), 48u);
  expect_valid_surface(mesh, 0, 2);
  expect_normals_away_from_axis(mesh);
  for (const Vec3& p : mesh.vertices) {
    const double s = p.z() / 3.0 + 0.5;
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0 - 0.75 * s, 1e-12);
  }
  expect_valid_surface(cone_frustum(), 0, 2);
}

TEST(Generate, SphereCountsAndVolume) {
  for (int k = 0; k <= 3; ++k) {
    const TriangleMesh mesh = sphere({.radius = 2.0, .subdivisions = k});
    const std::size_t power = std::size_t{1} << (2 * k);
    EXPECT_EQ(mesh.vertices.size(), 10 * power + 2);
    EXPECT_EQ(mesh.triangles.size(), 20 * power);
    expect_valid_surface(mesh, 2, 0);
    for (const Vec3& p : mesh.vertices) EXPECT_NEAR(p.norm(), 2.0, 1e-12);
  }
  const double exact = 4.0 / 3.0 * kPi;
  const double volume = signed_volume(sphere());
  EXPECT_LT(volume, exact);  // inscribed
  EXPECT_NEAR(volume / exact, 1.0, 0.03);
}

TEST(Generate, TorusCountsGenusAndVolume) {
  const TriangleMesh mesh = torus();
  EXPECT_EQ(mesh.vertices.size(), 48u * 24u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 48u * 24u);
  expect_valid_surface(mesh, 0, 0);
  const double exact = 2.0 * kPi * kPi * 1.0 * 0.35 * 0.35;
  EXPECT_NEAR(signed_volume(mesh) / exact, 1.0, 0.03);
  const TriangleMesh coarse =
      torus({.major_radius = 3.0, .minor_radius = 1.0, .segments = 3, .tube_segments = 3});
  EXPECT_EQ(coarse.vertices.size(), 9u);
  EXPECT_EQ(coarse.triangles.size(), 18u);
  expect_valid_surface(coarse, 0, 0);
}

TEST(Generate, FigureEightIsClosedGenusTwo) {
  const TriangleMesh mesh = figure_eight();
  EXPECT_GE(mesh.triangles.size(), 1500u);
  EXPECT_LE(mesh.triangles.size(), 3000u);
  expect_valid_surface(mesh, -2, 0);
  EXPECT_EQ(mesh.vertices.size() + 2, mesh.triangles.size() / 2);  // closed: V = F/2 + chi
  const double one_torus = 2.0 * kPi * kPi * 1.0 * 0.35 * 0.35;
  const double volume = signed_volume(mesh);
  EXPECT_GT(volume, 1.6 * one_torus);
  EXPECT_LT(volume, 2.2 * one_torus);
  const auto [lo, hi] = bounding_box(mesh.vertices);
  EXPECT_NEAR(hi.x(), 1.175 + 1.35, 0.1);
  EXPECT_NEAR(lo.x(), -(1.175 + 1.35), 0.1);
  EXPECT_NEAR(hi.z(), 0.35, 0.05);
  EXPECT_GT(minimum_angle_degrees(mesh), 20.0);
}

TEST(Generate, FigureEightStaysGenusTwoAcrossResolutionsAndSizes) {
  for (int resolution : {29, 37, 48, 64}) {
    SCOPED_TRACE("resolution " + std::to_string(resolution));
    const TriangleMesh mesh = figure_eight({.resolution = resolution});
    expect_valid_surface(mesh, -2, 0);
    EXPECT_GT(minimum_angle_degrees(mesh), 20.0);
  }
  SCOPED_TRACE("thick, sharp union");
  const TriangleMesh thick =
      figure_eight({.major_radius = 2.0, .minor_radius = 1.0, .blend = 0.0, .resolution = 28});
  expect_valid_surface(thick, -2, 0);
  EXPECT_GT(minimum_angle_degrees(thick), 20.0);
  EXPECT_THROW(figure_eight({.resolution = 28}), InvalidInputException);
}

TEST(Generate, PawnIsClosedSurfaceOfRevolution) {
  const TriangleMesh mesh = pawn();
  EXPECT_EQ(mesh.vertices.size(), 32u * 40u + 2u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 32u * 40u);
  expect_valid_surface(mesh, 2, 0);
  const auto [lo, hi] = bounding_box(mesh.vertices);
  EXPECT_NEAR(lo.z(), 0.0, 1e-12);
  EXPECT_NEAR(hi.z(), 2.0 * 0.97, 1e-12);
  EXPECT_NEAR(hi.x(), 2.0 * 0.36, 1e-12);
  const TriangleMesh coarse = pawn({.height = 1.0, .segments = 3, .profile_samples = 7});
  EXPECT_EQ(coarse.vertices.size(), 23u);
  EXPECT_EQ(coarse.triangles.size(), 42u);
  expect_valid_surface(coarse, 2, 0);
}

TEST(Generate, CylinderTwoHolesHasFourLoops) {
  const TriangleMesh mesh = cylinder_two_holes();
  EXPECT_EQ(mesh.vertices.size(), 32u * 13u - 2u * 5u * 3u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 32u * 12u - 4u * 6u * 4u);
  expect_valid_surface(mesh, -2, 4);
  expect_normals_away_from_axis(mesh);
  const auto loops = boundary_loops(to_mesh(mesh));
  ASSERT_EQ(loops.size(), 4u);
  EXPECT_EQ(loops[2].size(), 2u * (6u + 4u));
  EXPECT_EQ(loops[3].size(), 2u * (6u + 4u));

  const TriangleMesh tight =
      cylinder_two_holes({.segments = 6, .rings = 3, .hole_segments = 2, .hole_rings = 1});
  EXPECT_EQ(tight.vertices.size(), 24u);
  EXPECT_EQ(tight.triangles.size(), 36u - 8u);
  expect_valid_surface(tight, -2, 4);
}

TEST(Generate, BoxHasCreasesAndExactVolume) {
  const TriangleMesh mesh = box();
  EXPECT_EQ(mesh.vertices.size(), 9u * 7u * 5u - 7u * 5u * 3u);
  EXPECT_EQ(mesh.triangles.size(), 4u * (8u * 6u + 6u * 4u + 4u * 8u));
  expect_valid_surface(mesh, 2, 0);
  EXPECT_NEAR(signed_volume(mesh), 2.0 * 1.5 * 1.0, 1e-12);
  EXPECT_EQ(sharp_edge_count(mesh), 4 * (8 + 6 + 4));  // the 12 box edges
  const TriangleMesh cube = box({.size_x = 1,
                                 .size_y = 1,
                                 .size_z = 1,
                                 .divisions_x = 1,
                                 .divisions_y = 1,
                                 .divisions_z = 1});
  EXPECT_EQ(cube.vertices.size(), 8u);
  EXPECT_EQ(cube.triangles.size(), 12u);
  expect_valid_surface(cube, 2, 0);
}

TEST(Generate, CappedCylinderHasFlatCapsAndRimCreases) {
  const TriangleMesh mesh = capped_cylinder();
  const std::size_t circles = 8 + 2 * 4 - 1;
  EXPECT_EQ(mesh.vertices.size(), 32u * circles + 2u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 32u * circles);
  expect_valid_surface(mesh, 2, 0);
  const double prism = 0.5 * 32 * std::sin(2.0 * kPi / 32) * 2.0;  // polygonal cross-section
  EXPECT_NEAR(signed_volume(mesh), prism, 1e-12);
  EXPECT_EQ(sharp_edge_count(mesh), 2 * 32);
  expect_valid_surface(capped_cylinder({.segments = 3, .rings = 1, .cap_rings = 1}), 2, 0);
}

TEST(Generate, DumbbellIsGenusZeroWithAnalyticVolume) {
  const TriangleMesh mesh = dumbbell();
  const std::size_t circles = 2 * 12 + 6 - 1;
  EXPECT_EQ(mesh.vertices.size(), 32u * circles + 2u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 32u * circles);
  expect_valid_surface(mesh, 2, 0);
  const double radius = 1.0, bar = 0.3, length = 1.5;
  const double cap = radius - std::sqrt(radius * radius - bar * bar);
  const double exact =
      2.0 * (4.0 / 3.0 * kPi * std::pow(radius, 3) - kPi * cap * cap * (3.0 * radius - cap) / 3.0) +
      kPi * bar * bar * length;
  EXPECT_NEAR(signed_volume(mesh) / exact, 1.0, 0.05);
  const auto [lo, hi] = bounding_box(mesh.vertices);
  EXPECT_NEAR(hi.z(), 0.75 + std::sqrt(1.0 - 0.09) + 1.0, 1e-12);
  EXPECT_NEAR(lo.z(), -hi.z(), 1e-12);
}

const std::map<std::string, std::pair<int, int>> kTopology = {
    {"open_cylinder", {0, 2}}, {"elliptic_cylinder", {0, 2}},
    {"cone_frustum", {0, 2}},  {"sphere", {2, 0}},
    {"torus", {0, 0}},         {"figure_eight", {-2, 0}},
    {"pawn", {2, 0}},          {"cylinder_two_holes", {-2, 4}},
    {"box", {2, 0}},           {"capped_cylinder", {2, 0}},
    {"dumbbell", {2, 0}}};

TEST(Generate, EveryNamedShapeIsAValidSurface) {
  const std::vector<std::string> names = shape_names();
  EXPECT_EQ(names,
            (std::vector<std::string>{"open_cylinder", "elliptic_cylinder", "cone_frustum",
                                      "sphere", "torus", "figure_eight", "pawn",
                                      "cylinder_two_holes", "box", "capped_cylinder", "dumbbell"}));
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    ASSERT_EQ(kTopology.count(name), 1u);
    EXPECT_FALSE(shape_description(name).empty());
    const TriangleMesh mesh = generate_shape(name, {});
    expect_valid_surface(mesh, kTopology.at(name).first, kTopology.at(name).second);
    // Passing every parameter at its advertised default changes nothing.
    std::map<std::string, double> defaults;
    for (const ShapeParameter& parameter : shape_parameters(name)) {
      EXPECT_FALSE(parameter.description.empty());
      defaults[parameter.name] = parameter.default_value;
    }
    const TriangleMesh again = generate_shape(name, defaults);
    EXPECT_EQ(again.triangles, mesh.triangles);
    EXPECT_EQ(again.vertices, mesh.vertices);
  }
}

TEST(Generate, DispatcherAppliesParameters) {
  const TriangleMesh mesh = generate_shape("open_cylinder", {{"segments", 5}, {"rings", 3}});
  EXPECT_EQ(mesh.vertices.size(), 20u);
  EXPECT_EQ(mesh.triangles.size(), 30u);
  const TriangleMesh ball = generate_shape("sphere", {{"radius", 3.0}, {"subdivisions", 1}});
  EXPECT_EQ(ball.triangles.size(), 80u);
  EXPECT_NEAR(ball.vertices[0].norm(), 3.0, 1e-12);
  const auto parameters = shape_parameters("torus");
  ASSERT_EQ(parameters.size(), 4u);
  EXPECT_EQ(parameters[0].name, "major_radius");
  EXPECT_EQ(parameters[3].name, "tube_segments");
  EXPECT_EQ(parameters[3].default_value, TorusOptions{}.tube_segments);
}

// Runs `call`, expects InvalidInputException, and returns its message.
template <class Call>
std::string invalid_input_message(Call call) {
  try {
    call();
  } catch (const InvalidInputException& error) {
    return error.what();
  } catch (...) {
    ADD_FAILURE() << "threw something other than InvalidInputException";
    return {};
  }
  ADD_FAILURE() << "did not throw";
  return {};
}

TEST(Generate, DispatcherErrorsNameTheProblem) {
  const auto has = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  std::string message = invalid_input_message([] { generate_shape("dodecahedron", {}); });
  EXPECT_TRUE(has(message, "dodecahedron") && has(message, "figure_eight") && has(message, "pawn"))
      << message;
  message = invalid_input_message([] { shape_parameters("cube"); });
  EXPECT_TRUE(has(message, "box")) << message;
  message = invalid_input_message([] { generate_shape("torus", {{"radius", 1.0}}); });
  EXPECT_TRUE(has(message, "'radius'") && has(message, "minor_radius") &&
              has(message, "tube_segments"))
      << message;
  message = invalid_input_message([] { generate_shape("open_cylinder", {{"radius", -1.0}}); });
  EXPECT_TRUE(has(message, "open_cylinder") && has(message, "radius") && has(message, "-1"))
      << message;
  message = invalid_input_message([] { generate_shape("open_cylinder", {{"segments", 2}}); });
  EXPECT_TRUE(has(message, "segments") && has(message, "at least 3")) << message;
  message = invalid_input_message([] { generate_shape("sphere", {{"subdivisions", 1.5}}); });
  EXPECT_TRUE(has(message, "integer")) << message;
  message = invalid_input_message([] { generate_shape("sphere", {{"radius", std::nan("")}}); });
  EXPECT_TRUE(has(message, "radius")) << message;
  message = invalid_input_message([] { generate_shape("torus", {{"minor_radius", 1.5}}); });
  EXPECT_TRUE(has(message, "smaller than major_radius")) << message;
  message = invalid_input_message([] { generate_shape("figure_eight", {{"resolution", 10}}); });
  EXPECT_TRUE(has(message, "at least 29")) << message;
  message = invalid_input_message([] {
    generate_shape("cylinder_two_holes", {{"hole_segments", 16}});
  });
  EXPECT_TRUE(has(message, "hole_segments")) << message;
  message = invalid_input_message([] { generate_shape("dumbbell", {{"handle_radius", 1.0}}); });
  EXPECT_TRUE(has(message, "handle_radius")) << message;
  message = invalid_input_message([] {
    generate_shape("box", {{"divisions_x", 1e6}, {"divisions_y", 1e6}});
  });
  EXPECT_TRUE(has(message, "limit")) << message;
  invalid_input_message([] { generate_shape("pawn", {{"profile_samples", 6}}); });
  invalid_input_message([] { generate_shape("cone_frustum", {{"top_radius", 0.0}}); });
  invalid_input_message([] { generate_shape("capped_cylinder", {{"cap_rings", 0}}); });
  invalid_input_message([] { generate_shape("figure_eight", {{"blend", 0.5}}); });
}

}  // namespace
}  // namespace papercraft
