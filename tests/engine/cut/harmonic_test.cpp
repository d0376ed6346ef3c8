#include "engine/cut/harmonic.h"

#include <gtest/gtest.h>

#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "core/errors.h"
#include "core/labelled_soup.h"

namespace papercraft {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Indexed triangles plus texture coordinates; unused vertices are dropped by make_mesh.
struct Soup {
  std::vector<Vec3> points;
  std::vector<Vec2> uv;
  std::vector<Triangle> triangles;
};

// OpenMesh mesh with texcoords and "v:input_vertex" = own index.
Mesh make_mesh(const Soup& soup) {
  std::vector<int> remap(soup.points.size(), -1);
  for (const Triangle& t : soup.triangles)
    for (int v : t) remap[v] = 0;
  TriangleMesh compact;
  std::vector<Vec2> uv;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (remap[v] < 0) continue;
    remap[v] = static_cast<int>(compact.vertices.size());
    compact.vertices.push_back(soup.points[v]);
    uv.push_back(soup.uv[v]);
  }
  for (const Triangle& t : soup.triangles)
    compact.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  Mesh mesh = to_mesh(compact);
  mesh.request_vertex_texcoords2D();
  auto input_vertex =
      OpenMesh::getOrMakeProperty<OpenMesh::VertexHandle, int>(mesh, "v:input_vertex");
  for (auto v : mesh.vertices()) {
    mesh.set_texcoord2D(v, OpenMesh::Vec2d(uv[v.idx()][0], uv[v.idx()][1]));
    input_vertex[v] = v.idx();
  }
  return mesh;
}

// Cylinder of radius 1 and height 2 (z in [0, 2]) with `rings` rings of `around` vertices;
// quads (i, k) with i in hole_i and k in hole_k are left out (a hole).
Mesh grid_cylinder(int around, int rings, std::set<int> hole_i = {}, std::set<int> hole_k = {}) {
  Soup soup;
  for (int k = 0; k < rings; ++k) {
    for (int i = 0; i < around; ++i) {
      const double angle = 2 * kPi * i / around;
      soup.points.emplace_back(std::cos(angle), std::sin(angle), 2.0 * k / (rings - 1));
      soup.uv.emplace_back(double(i) / around, double(k) / (rings - 1));
    }
  }
  auto id = [&](int i, int k) { return k * around + (i % around); };
  for (int k = 0; k + 1 < rings; ++k) {
    for (int i = 0; i < around; ++i) {
      if (hole_i.count(i) && hole_k.count(k)) continue;
      soup.triangles.push_back({id(i, k), id(i + 1, k), id(i + 1, k + 1)});
      soup.triangles.push_back({id(i, k), id(i + 1, k + 1), id(i, k + 1)});
    }
  }
  return make_mesh(soup);
}

// Flat grid [0, width] x [0, height] of nx by ny vertices, diagonals (i,j)-(i+1,j+1); with
// jitter, vertices move inside the rectangle (boundary vertices only along their side).
Mesh flat_grid(int nx, int ny, double width, double height, double jitter) {
  Soup soup;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      double x = width * i / (nx - 1);
      double y = height * j / (ny - 1);
      if (i > 0 && i + 1 < nx) x += jitter * width / (nx - 1) * std::sin(1.7 * i + 2.3 * j);
      if (j > 0 && j + 1 < ny) y += jitter * height / (ny - 1) * std::cos(2.9 * i + 0.7 * j);
      soup.points.emplace_back(x, y, 0.0);
      soup.uv.emplace_back(x / width, y / height);
    }
  }
  auto id = [&](int i, int j) { return j * nx + i; };
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      soup.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      soup.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return make_mesh(soup);
}

// UV sphere of radius 1: north pole 0, south pole last, `stacks` - 1 rings of `slices`.
Mesh uv_sphere(int slices, int stacks) {
  Soup soup;
  soup.points.emplace_back(0, 0, 1);
  soup.uv.emplace_back(0.5, 1.0);
  for (int s = 1; s < stacks; ++s) {
    const double polar = kPi * s / stacks;
    for (int i = 0; i < slices; ++i) {
      const double angle = 2 * kPi * i / slices;
      soup.points.emplace_back(std::sin(polar) * std::cos(angle), std::sin(polar) * std::sin(angle),
                               std::cos(polar));
      soup.uv.emplace_back(double(i) / slices, 1.0 - double(s) / stacks);
    }
  }
  const int south = static_cast<int>(soup.points.size());
  soup.points.emplace_back(0, 0, -1);
  soup.uv.emplace_back(0.5, 0.0);
  auto id = [&](int s, int i) { return 1 + (s - 1) * slices + (i % slices); };
  for (int i = 0; i < slices; ++i) {
    soup.triangles.push_back({0, id(1, i), id(1, i + 1)});
    soup.triangles.push_back({south, id(stacks - 1, i + 1), id(stacks - 1, i)});
  }
  for (int s = 1; s + 1 < stacks; ++s) {
    for (int i = 0; i < slices; ++i) {
      soup.triangles.push_back({id(s, i), id(s + 1, i), id(s + 1, i + 1)});
      soup.triangles.push_back({id(s, i), id(s + 1, i + 1), id(s, i + 1)});
    }
  }
  return make_mesh(soup);
}

std::vector<int> vertices_where(const Mesh& mesh, const std::function<bool(const Vec3&)>& pred) {
  std::vector<int> out;
  for (auto v : mesh.vertices())
    if (pred(to_eigen(mesh.point(v)))) out.push_back(v.idx());
  return out;
}

int input_vertex_of(const Mesh& mesh, Mesh::VertexHandle v) {
  OpenMesh::VPropHandleT<int> handle;
  EXPECT_TRUE(mesh.get_property_handle(handle, "v:input_vertex"));
  return mesh.property(handle, v);
}

using Key = std::array<double, 3>;
Key key_of(const OpenMesh::Vec3d& p) {
  return {p[0], p[1], p[2]};
}

void expect_valid_manifold(const Mesh& part) {
  ASSERT_GT(part.n_faces(), 0u);
  for (auto v : part.vertices()) {
    EXPECT_TRUE(part.is_manifold(v)) << "non-manifold vertex " << v.idx();
    EXPECT_FALSE(part.is_isolated(v)) << "isolated vertex " << v.idx();
  }
  EXPECT_NO_THROW(to_mesh(to_triangle_mesh(part)));
  for (auto f : part.faces()) EXPECT_GT(part.calc_face_area(f), 1e-6) << "degenerate face";
}

// Every vertex of every part is either an input vertex (same position and uv) or lies on an
// input edge where the linear interpolation of f equals `value` and uv is interpolated.
// Returns the number of new vertices.
int check_vertices_against_input(const Mesh& input, const Eigen::VectorXd& f, double value,
                                 const std::vector<Mesh>& parts) {
  int created = 0;
  for (const Mesh& part : parts) {
    EXPECT_TRUE(part.has_vertex_texcoords2D());
    for (auto v : part.vertices()) {
      const int origin = input_vertex_of(part, v);
      const auto p = part.point(v);
      const auto uv = part.texcoord2D(v);
      if (origin >= 0) {
        auto w = input.vertex_handle(origin);
        EXPECT_EQ(p, input.point(w));
        EXPECT_EQ(uv, input.texcoord2D(w));
        continue;
      }
      ++created;
      int found = 0;
      for (auto e : input.edges()) {
        const auto a = input.point(e.v0());
        const auto b = input.point(e.v1());
        const double t = OpenMesh::dot(p - a, b - a) / (b - a).sqrnorm();
        if (t <= 0.0 || t >= 1.0 || (a + t * (b - a) - p).norm() > 1e-12) continue;
        ++found;
        EXPECT_NEAR((1 - t) * f[e.v0().idx()] + t * f[e.v1().idx()], value, 1e-9);
        const auto expected_uv = (1 - t) * input.texcoord2D(e.v0()) + t * input.texcoord2D(e.v1());
        EXPECT_NEAR((uv - expected_uv).norm(), 0.0, 1e-12);
      }
      EXPECT_EQ(found, 1) << "new vertex at " << p << " is not inside exactly one input edge";
    }
  }
  return created;
}

double total_area(const std::vector<Mesh>& parts) {
  double area = 0;
  for (const Mesh& part : parts) area += surface_area(part);
  return area;
}

// Boundary edges of `part` whose endpoints are both in `on_cut`, as unordered coordinate pairs.
std::set<std::pair<Key, Key>> cut_edges(const Mesh& part, const std::set<Key>& on_cut) {
  std::set<std::pair<Key, Key>> edges;
  for (auto e : part.edges()) {
    if (!e.is_boundary()) continue;
    Key a = key_of(part.point(e.v0()));
    Key b = key_of(part.point(e.v1()));
    if (!on_cut.count(a) || !on_cut.count(b)) continue;
    if (b < a) std::swap(a, b);
    edges.insert({a, b});
  }
  return edges;
}

std::set<Key> new_vertex_keys(const Mesh& part) {
  std::set<Key> keys;
  for (auto v : part.vertices())
    if (input_vertex_of(part, v) < 0) keys.insert(key_of(part.point(v)));
  return keys;
}

// ---------------------------------------------------------------------------------------

TEST(HarmonicField, LinearInHeightOnCylinder) {
  const Mesh cylinder = grid_cylinder(16, 9);
  const auto bottom = vertices_where(cylinder, [](const Vec3& p) { return p.z() == 0.0; });
  const auto top = vertices_where(cylinder, [](const Vec3& p) { return p.z() == 2.0; });
  ASSERT_EQ(bottom.size(), 16u);
  ASSERT_EQ(top.size(), 16u);
  const Eigen::VectorXd f = harmonic_field(cylinder, bottom, top);
  ASSERT_EQ(f.size(), static_cast<Eigen::Index>(cylinder.n_vertices()));
  for (auto v : cylinder.vertices()) EXPECT_NEAR(f[v.idx()], cylinder.point(v)[2] / 2, 1e-9);
}

// Jittered interior vertices give obtuse triangles and negative weights; linear precision
// of the cotangent Laplacian must still hold (uniform weights would fail here).
TEST(HarmonicField, LinearOnJitteredFlatRectangle) {
  const Mesh rectangle = flat_grid(8, 5, 3.0, 1.0, 0.2);
  for (auto f : rectangle.faces()) ASSERT_GT(rectangle.calc_face_normal(f)[2], 0.0);
  const auto left = vertices_where(rectangle, [](const Vec3& p) { return p.x() == 0.0; });
  const auto right = vertices_where(rectangle, [](const Vec3& p) { return p.x() == 3.0; });
  ASSERT_EQ(left.size(), 5u);
  ASSERT_EQ(right.size(), 5u);
  const Eigen::VectorXd f = harmonic_field(rectangle, left, right);
  for (auto v : rectangle.vertices()) EXPECT_NEAR(f[v.idx()], rectangle.point(v)[0] / 3, 1e-9);

  HarmonicOptions clamped;
  clamped.clamp_negative_weights = true;
  const Eigen::VectorXd g = harmonic_field(rectangle, left, right, clamped);
  for (int v = 0; v < g.size(); ++v) {
    EXPECT_GE(g[v], 0.0);
    EXPECT_LE(g[v], 1.0);
  }
  EXPECT_GT((f - g).cwiseAbs().maxCoeff(), 1e-6) << "clamping should change an obtuse mesh";
}

// Point constraints at the poles: free values strictly inside (0, 1), constant on each ring
// and decreasing from north to south (maximum principle and symmetry).
TEST(HarmonicField, MaximumPrincipleOnSphere) {
  const Mesh sphere = uv_sphere(12, 8);
  const int south = static_cast<int>(sphere.n_vertices()) - 1;
  const Eigen::VectorXd f = harmonic_field(sphere, {0}, {south});
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[south], 1.0);
  double previous = 0.0;
  for (int s = 1; s < 8; ++s) {
    const double ring = f[1 + (s - 1) * 12];
    EXPECT_GT(ring, previous);
    EXPECT_LT(ring, 1.0);
    for (int i = 0; i < 12; ++i) EXPECT_NEAR(f[1 + (s - 1) * 12 + i], ring, 1e-9);
    previous = ring;
  }
}

TEST(HarmonicField, ComponentWithoutConstraint) {
  Mesh two = grid_cylinder(8, 3);
  const Mesh other = grid_cylinder(8, 3);
  std::vector<Mesh::VertexHandle> handles;
  for (auto v : other.vertices())
    handles.push_back(two.add_vertex(other.point(v) + OpenMesh::Vec3d(5, 0, 0)));
  for (auto f : other.faces()) {
    std::vector<Mesh::VertexHandle> face;
    for (auto v : f.vertices()) face.push_back(handles[v.idx()]);
    two.add_face(face);
  }
  const auto bottom = vertices_where(two, [](const Vec3& p) { return p.z() == 0 && p.x() < 2; });
  const auto top = vertices_where(two, [](const Vec3& p) { return p.z() == 2 && p.x() < 2; });
  EXPECT_THROW(harmonic_field(two, bottom, top), TopologyException);

  HarmonicOptions options;
  options.allow_unconstrained_components = true;
  options.unconstrained_value = 0.25;
  const Eigen::VectorXd f = harmonic_field(two, bottom, top, options);
  for (auto v : two.vertices()) {
    const double expected = two.point(v)[0] > 2 ? 0.25 : two.point(v)[2] / 2;
    EXPECT_NEAR(f[v.idx()], expected, 1e-9);
  }
}

TEST(HarmonicField, BadInput) {
  const Mesh cylinder = grid_cylinder(8, 3);
  EXPECT_THROW(harmonic_field(cylinder, {}, {1}), InvalidInputException);
  EXPECT_THROW(harmonic_field(cylinder, {0}, {}), InvalidInputException);
  EXPECT_THROW(harmonic_field(cylinder, {0}, {0}), InvalidInputException);
  EXPECT_THROW(harmonic_field(cylinder, {0}, {1000}), InvalidInputException);
  EXPECT_THROW(harmonic_field(cylinder, {-1}, {1}), InvalidInputException);
}

TEST(FieldValueAt, ClosestPointInterpolation) {
  const Mesh cylinder = grid_cylinder(16, 9);
  const auto bottom = vertices_where(cylinder, [](const Vec3& p) { return p.z() == 0.0; });
  const auto top = vertices_where(cylinder, [](const Vec3& p) { return p.z() == 2.0; });
  const Eigen::VectorXd f = harmonic_field(cylinder, bottom, top);
  EXPECT_NEAR(field_value_at(cylinder, f, Vec3(1.5 * std::cos(0.1), 1.5 * std::sin(0.1), 0.7)),
              0.35, 1e-9);
  EXPECT_NEAR(field_value_at(cylinder, f, Vec3(0.2, 0.1, 1.3)), 0.65, 1e-9);
  EXPECT_NEAR(field_value_at(cylinder, f, Vec3(1, 0, 5)), 1.0, 1e-9);
  EXPECT_THROW(field_value_at(cylinder, Eigen::VectorXd::Zero(3), Vec3(0, 0, 0)),
               InvalidInputException);
}

TEST(HoleSplitValue, MidpointOfLoopRange) {
  Eigen::VectorXd f(5);
  f << 0.0, 0.2, 0.9, 0.4, 1.0;
  EXPECT_DOUBLE_EQ(hole_split_value(f, {1, 2, 3}), 0.55);
  EXPECT_THROW(hole_split_value(f, {}), InvalidInputException);
  EXPECT_THROW(hole_split_value(f, {1, 7}), InvalidInputException);
}

// ---------------------------------------------------------------------------------------

class CylinderCut : public ::testing::Test {
 protected:
  void SetUp() override {
    bottom_ = vertices_where(cylinder_, [](const Vec3& p) { return p.z() == 0.0; });
    top_ = vertices_where(cylinder_, [](const Vec3& p) { return p.z() == 2.0; });
    harmonic_ = harmonic_field(cylinder_, bottom_, top_);
    exact_.resize(cylinder_.n_vertices());
    for (auto v : cylinder_.vertices()) exact_[v.idx()] = cylinder_.point(v)[2] / 2;  // k / 8
  }
  static double side_area(double height) { return 16 * 2 * std::sin(kPi / 16) * height; }

  Mesh cylinder_ = grid_cylinder(16, 9);
  std::vector<int> bottom_, top_;
  Eigen::VectorXd harmonic_, exact_;
};

TEST_F(CylinderCut, AcrossGivesTwoCylindersSharingTheCut) {
  const double value = 0.3;  // between the rings at f = 0.25 and 0.375: crossing at t = 0.4
  const auto parts = cut_along_isoline(cylinder_, harmonic_, value);
  ASSERT_EQ(parts.size(), 2u);
  for (const Mesh& part : parts) {
    expect_valid_manifold(part);
    EXPECT_EQ(euler_characteristic(part), 0);
    EXPECT_EQ(boundary_loops(part).size(), 2u);
    EXPECT_EQ(connected_components(part), 1);
  }
  EXPECT_NEAR(surface_area(parts[0]), side_area(0.6), 1e-9 * side_area(2));
  EXPECT_NEAR(surface_area(parts[1]), side_area(1.4), 1e-9 * side_area(2));
  EXPECT_NEAR(total_area(parts), surface_area(cylinder_), 1e-9 * surface_area(cylinder_));
  // 16 vertical and 16 diagonal edges are crossed.
  EXPECT_EQ(check_vertices_against_input(cylinder_, harmonic_, value, parts), 2 * 32);
  // Below the cut first.
  for (auto v : parts[0].vertices()) EXPECT_LE(parts[0].point(v)[2], 0.6 + 1e-9);
  for (auto v : parts[1].vertices()) EXPECT_GE(parts[1].point(v)[2], 0.6 - 1e-9);

  const std::set<Key> below = new_vertex_keys(parts[0]);
  const std::set<Key> above = new_vertex_keys(parts[1]);
  EXPECT_EQ(below.size(), 32u);
  EXPECT_EQ(below, above);
  const auto below_edges = cut_edges(parts[0], below);
  EXPECT_EQ(below_edges.size(), 32u);
  EXPECT_EQ(below_edges, cut_edges(parts[1], above));
}

TEST_F(CylinderCut, ValueOnARingCreatesNoVertices) {
  CutOptions no_snap;
  no_snap.snap_fraction = 0.0;
  const auto parts = cut_along_isoline(cylinder_, exact_, 0.5, no_snap);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(check_vertices_against_input(cylinder_, exact_, 0.5, parts), 0);
  EXPECT_EQ(parts[0].n_vertices(), 5u * 16);
  EXPECT_EQ(parts[1].n_vertices(), 5u * 16);
  for (const Mesh& part : parts) {
    expect_valid_manifold(part);
    EXPECT_EQ(euler_characteristic(part), 0);
    EXPECT_EQ(boundary_loops(part).size(), 2u);
  }
}

TEST_F(CylinderCut, CrossingNearARingSnaps) {
  const double value = 0.5 + 0.125 * 0.03;  // 3% of the edge above ring 4
  const auto snapped = cut_along_isoline(cylinder_, exact_, value);
  ASSERT_EQ(snapped.size(), 2u);
  EXPECT_EQ(check_vertices_against_input(cylinder_, exact_, 0.5, snapped), 0);
  EXPECT_EQ(snapped[0].n_vertices(), 5u * 16);
  EXPECT_EQ(snapped[1].n_vertices(), 5u * 16);
  EXPECT_NEAR(total_area(snapped), surface_area(cylinder_), 1e-9 * surface_area(cylinder_));

  CutOptions fine;
  fine.snap_fraction = 0.01;
  const auto crossed = cut_along_isoline(cylinder_, exact_, value, fine);
  ASSERT_EQ(crossed.size(), 2u);
  EXPECT_EQ(check_vertices_against_input(cylinder_, exact_, value, crossed), 2 * 32);

  // The crossing lies 0.0075 above the ring on the vertical edges (0.25 long) and about as
  // close on the diagonals: an absolute snap distance above that snaps it whatever the
  // fraction, one below does not.
  CutOptions near = fine;
  near.snap_distance = 0.01;
  const auto near_snapped = cut_along_isoline(cylinder_, exact_, value, near);
  ASSERT_EQ(near_snapped.size(), 2u);
  EXPECT_EQ(check_vertices_against_input(cylinder_, exact_, 0.5, near_snapped), 0);
  near.snap_distance = 0.005;
  EXPECT_EQ(check_vertices_against_input(cylinder_, exact_, value,
                                         cut_along_isoline(cylinder_, exact_, value, near)),
            2 * 32);
}

TEST_F(CylinderCut, OutsideRangeReturnsPartUnchanged) {
  for (double value : {-0.1, 0.0, 1.0, 1.5}) {
    const auto parts = cut_along_isoline(cylinder_, harmonic_, value);
    ASSERT_EQ(parts.size(), 1u);
    EXPECT_EQ(parts[0].n_vertices(), cylinder_.n_vertices());
    EXPECT_EQ(parts[0].n_faces(), cylinder_.n_faces());
  }
}

TEST_F(CylinderCut, BadInput) {
  EXPECT_THROW(cut_along_isoline(cylinder_, Eigen::VectorXd::Zero(4), 0.5), InvalidInputException);
  CutOptions bad;
  bad.snap_fraction = 0.5;
  EXPECT_THROW(cut_along_isoline(cylinder_, harmonic_, 0.5, bad), InvalidInputException);
  bad = CutOptions{};
  bad.snap_distance = -1e-3;
  EXPECT_THROW(cut_along_isoline(cylinder_, harmonic_, 0.5, bad), InvalidInputException);
  EXPECT_THROW(cut_along_isoline(cylinder_, harmonic_, std::nan("")), InvalidInputException);
  Mesh with_deleted = cylinder_;
  with_deleted.delete_face(with_deleted.face_handle(0), false);
  EXPECT_THROW(cut_along_isoline(with_deleted, harmonic_, 0.5), InvalidInputException);
  EXPECT_THROW(harmonic_field(with_deleted, bottom_, top_), InvalidInputException);
  EXPECT_THROW(split_connected_components(with_deleted), InvalidInputException);
}

TEST(Cut, PropertiesAreOptional) {
  TriangleMesh square;
  square.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Mesh mesh = to_mesh(square);
  Eigen::VectorXd f(4);
  f << 0, 1, 1, 0;
  const auto parts = cut_along_isoline(mesh, f, 0.5);
  ASSERT_EQ(parts.size(), 2u);
  for (const Mesh& part : parts) {
    EXPECT_FALSE(part.has_vertex_texcoords2D());
    EXPECT_FALSE((OpenMesh::hasProperty<OpenMesh::VertexHandle, int>(part, "v:input_vertex")));
    expect_valid_manifold(part);
    EXPECT_NEAR(surface_area(part), 0.5, 1e-12);
  }
}

// The iso-line f = 0 passes twice through the centre vertex c = (3, 3): the region f > 0
// touches itself at c and must get two copies of c to stay a manifold (an annulus).
TEST(Cut, PinchedVertexIsDuplicated) {
  const Mesh grid = flat_grid(7, 7, 6.0, 6.0, 0.0);
  Eigen::VectorXd f = Eigen::VectorXd::Ones(grid.n_vertices());
  auto id = [](int i, int j) { return j * 7 + i; };
  f[id(2, 2)] = -1;
  f[id(4, 4)] = -1;
  f[id(3, 3)] = 0;
  const auto parts = cut_along_isoline(grid, f, 0.0);
  ASSERT_EQ(parts.size(), 3u);
  for (const Mesh& part : parts) expect_valid_manifold(part);
  for (int diamond : {0, 1}) {
    EXPECT_EQ(parts[diamond].n_vertices(), 7u);
    EXPECT_EQ(parts[diamond].n_faces(), 6u);
    EXPECT_EQ(euler_characteristic(parts[diamond]), 1);
    EXPECT_EQ(boundary_loops(parts[diamond]).size(), 1u);
  }
  EXPECT_EQ(euler_characteristic(parts[2]), 0);
  EXPECT_EQ(boundary_loops(parts[2]).size(), 2u);
  int copies = 0;
  for (auto v : parts[2].vertices()) copies += parts[2].point(v) == OpenMesh::Vec3d(3, 3, 0);
  EXPECT_EQ(copies, 2);
  EXPECT_NEAR(total_area(parts), 36.0, 1e-9);
  EXPECT_EQ(check_vertices_against_input(grid, f, 0.0, parts), 5 + 5 + 10);
  EXPECT_EQ(new_vertex_keys(parts[0]).size() + new_vertex_keys(parts[1]).size(),
            new_vertex_keys(parts[2]).size());
}

TEST(Cut, SphereCutIntoTwoDisks) {
  const Mesh sphere = uv_sphere(12, 9);
  const int south = static_cast<int>(sphere.n_vertices()) - 1;
  const Eigen::VectorXd f = harmonic_field(sphere, {0}, {south});
  const double value = field_value_at(sphere, f, Vec3(2, 0.3, 0.1));
  const auto parts = cut_along_isoline(sphere, f, value);
  ASSERT_EQ(parts.size(), 2u);
  for (const Mesh& part : parts) {
    expect_valid_manifold(part);
    EXPECT_EQ(euler_characteristic(part), 1);
    EXPECT_EQ(boundary_loops(part).size(), 1u);
  }
  EXPECT_NEAR(total_area(parts), surface_area(sphere), 1e-9 * surface_area(sphere));
  EXPECT_GT(check_vertices_against_input(sphere, f, value, parts), 0);
}

// The paper splits a part at its holes regardless of the error: cutting at the hole's
// iso-value leaves no part with the hole as an internal (third) boundary.
TEST(Cut, HoleIsSplitOff) {
  const Mesh holed = grid_cylinder(16, 9, {3, 4}, {3, 4, 5});
  const auto loops = boundary_loops(holed);
  ASSERT_EQ(loops.size(), 3u);
  ASSERT_EQ(euler_characteristic(holed), -1);
  const auto bottom = vertices_where(holed, [](const Vec3& p) { return p.z() == 0.0; });
  const auto top = vertices_where(holed, [](const Vec3& p) { return p.z() == 2.0; });
  const std::vector<int>& hole = loops[2];
  ASSERT_EQ(hole.size(), 10u);
  const Eigen::VectorXd f = harmonic_field(holed, bottom, top);
  const double value = hole_split_value(f, hole);
  double low = 1, high = 0;
  for (int v : hole) {
    low = std::min(low, f[v]);
    high = std::max(high, f[v]);
  }
  EXPECT_GT(value, low);
  EXPECT_LT(value, high);

  const auto parts = cut_along_isoline(holed, f, value);
  ASSERT_GE(parts.size(), 2u);
  const std::set<int> hole_set(hole.begin(), hole.end());
  for (const Mesh& part : parts) {
    expect_valid_manifold(part);
    EXPECT_LE(boundary_loops(part).size(), 2u);
    int hole_vertices = 0;
    for (auto v : part.vertices()) hole_vertices += hole_set.count(input_vertex_of(part, v));
    EXPECT_LT(hole_vertices, 10);
  }
  EXPECT_NEAR(total_area(parts), surface_area(holed), 1e-9 * surface_area(holed));
  EXPECT_GT(check_vertices_against_input(holed, f, value, parts), 0);
}

// The cut between two pieces of a disc-like part: the points of a's boundary loop that b holds
// too (new vertices and input vertices on the line), in the loop's order.
std::vector<Vec3> cut_polyline(const Mesh& a, const Mesh& b) {
  std::set<std::array<double, 3>> in_b;
  for (auto v : b.vertices()) in_b.insert({b.point(v)[0], b.point(v)[1], b.point(v)[2]});
  Mesh::HalfedgeHandle start;
  for (auto h : a.halfedges())
    if (a.is_boundary(h)) {
      start = h;
      break;
    }
  std::vector<Vec3> loop;
  std::vector<char> on_cut;
  auto h = start;
  do {
    const auto p = a.point(a.to_vertex_handle(h));
    loop.emplace_back(p[0], p[1], p[2]);
    on_cut.push_back(in_b.count({p[0], p[1], p[2]}) ? 1 : 0);
    h = a.next_halfedge_handle(h);
  } while (h != start);
  const std::size_t n = loop.size();
  std::size_t first = 0;  // a point off the cut, so the cut is one run after it
  while (first < n && on_cut[first]) ++first;
  std::vector<Vec3> points;
  for (std::size_t k = 1; k <= n; ++k)
    if (on_cut[(first + k) % n]) points.push_back(loop[(first + k) % n]);
  return points;
}

double polyline_length(const std::vector<Vec3>& points) {
  double length = 0;
  for (std::size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

// Corners of the polyline turning by more than `degrees`.
int sharp_corners(const std::vector<Vec3>& points, double degrees) {
  int count = 0;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Vec3 a = points[i] - points[i - 1], b = points[i + 1] - points[i];
    if (std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0)) > degrees * kPi / 180)
      ++count;
  }
  return count;
}

// A field whose iso-line zig-zags across a flat grid (the middle row alternately above and below
// the iso-value, as the harmonic field does across long thin triangles): the exact iso-line
// turns sharply at almost every crossing; straightened (the default), each crossing slides
// along its edge and the cut runs nearly straight, still one new vertex per crossed edge,
// inside that edge, with its texture coordinates where it lies, and the pieces still cover
// the part.
TEST(Cut, StraighteningTakesTheZigZagOutOfACut) {
  const int nx = 41;
  const Mesh grid = flat_grid(nx, 3, 20.0, 2.0, 0.0);  // cells of 0.5 x 1
  Eigen::VectorXd f(grid.n_vertices());
  for (auto v : grid.vertices()) {
    const int i = v.idx() % nx, j = v.idx() / nx;
    f[v.idx()] = j == 1 ? 1.0 + (i % 2 ? 0.6 : -0.6) : j;
  }
  CutOptions exact, straight;
  exact.straighten_passes = 0;
  const auto zigzag = cut_along_isoline(grid, f, 1.0, exact);
  const auto cut = cut_along_isoline(grid, f, 1.0, straight);
  ASSERT_EQ(zigzag.size(), 2u);
  ASSERT_EQ(cut.size(), 2u);
  const std::vector<Vec3> before = cut_polyline(zigzag[0], zigzag[1]);
  const std::vector<Vec3> after = cut_polyline(cut[0], cut[1]);
  ASSERT_GE(after.size(), 2u);
  EXPECT_GT(sharp_corners(before, 60), 10);
  EXPECT_EQ(sharp_corners(after, 60), 0);
  EXPECT_LT(polyline_length(after), 0.8 * polyline_length(before));
  EXPECT_GT(polyline_length(after), 19.99);  // no shorter than the grid is wide
  for (const Mesh& part : cut) expect_valid_manifold(part);
  EXPECT_NEAR(total_area(cut), surface_area(grid), 1e-9 * surface_area(grid));
  // Each new vertex lies inside one input edge (a crossing slid along it, or snapped to an
  // input vertex), with the texture coordinates of where it lies.
  for (auto v : cut[0].vertices()) {
    if (input_vertex_of(cut[0], v) >= 0) continue;
    const Mesh::Point q = cut[0].point(v);
    int inside = 0;
    for (auto e : grid.edges()) {
      const auto a = grid.point(e.v0()), b = grid.point(e.v1());
      const double t = OpenMesh::dot(q - a, b - a) / (b - a).sqrnorm();
      if (t > 0.0 && t < 1.0 && (a + t * (b - a) - q).norm() < 1e-12) ++inside;
    }
    EXPECT_EQ(inside, 1) << q;
  }
  for (auto v : cut[0].vertices()) {
    const auto p = cut[0].point(v);
    const auto uv = cut[0].texcoord2D(v);
    EXPECT_NEAR(uv[0], p[0] / 20.0, 1e-12);
    EXPECT_NEAR(uv[1], p[1] / 2.0, 1e-12);
  }
}

// A gently curved iso-line (it turns far less than straighten_turn_degrees at each crossing)
// is cut where the field puts it, bit for bit: straightening it whole would pull the curve
// towards its chord and move the cut away from the point it was chosen through.
TEST(Cut, StraighteningLeavesASmoothIsoLineWhereItIs) {
  const int nx = 41;
  const Mesh grid = flat_grid(nx, 5, 20.0, 4.0, 0.0);
  Eigen::VectorXd f(grid.n_vertices());
  for (auto v : grid.vertices()) {
    const auto p = grid.point(v);
    f[v.idx()] = p[1] / 4.0 + 0.05 * std::sin(0.3 * p[0]);
  }
  CutOptions exact, every_crossing;
  exact.straighten_passes = 0;
  every_crossing.straighten_turn_degrees = 0.0;
  auto cut_points = [&](const CutOptions& options) {
    const auto pieces = cut_along_isoline(grid, f, 0.5, options);
    EXPECT_EQ(pieces.size(), 2u);
    return pieces.size() == 2 ? cut_polyline(pieces[0], pieces[1]) : std::vector<Vec3>{};
  };
  const std::vector<Vec3> field = cut_points(exact);
  ASSERT_GT(field.size(), 20u);
  EXPECT_EQ(sharp_corners(field, 30), 0);
  EXPECT_EQ(cut_points(CutOptions{}), field);
  EXPECT_NE(cut_points(every_crossing), field);
}

TEST(SplitConnectedComponents, SeparatesAndUnpinches) {
  // Two triangles sharing only vertex 0 (a bowtie) and a separate square.
  TriangleMesh soup;
  soup.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0),
                   Vec3(5, 0, 0), Vec3(6, 0, 0), Vec3(6, 1, 0), Vec3(5, 1, 0),  Vec3(9, 9, 9)};
  soup.triangles = {{0, 1, 2}, {5, 6, 7}, {0, 3, 4}, {5, 7, 8}};
  const Mesh mesh = to_mesh(soup);
  const auto parts = split_connected_components(mesh);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].n_vertices(), 3u);  // lowest face first
  EXPECT_EQ(parts[1].n_vertices(), 4u);
  EXPECT_EQ(parts[2].n_vertices(), 3u);
  for (const Mesh& part : parts) expect_valid_manifold(part);
  EXPECT_NEAR(total_area(parts), surface_area(mesh), 1e-12);

  const Mesh cylinder = grid_cylinder(8, 3);
  const auto one = split_connected_components(cylinder);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].n_vertices(), cylinder.n_vertices());
  EXPECT_TRUE(one[0].has_vertex_texcoords2D());
  EXPECT_EQ(input_vertex_of(one[0], one[0].vertex_handle(5)), 5);
}

}  // namespace
}  // namespace papercraft
