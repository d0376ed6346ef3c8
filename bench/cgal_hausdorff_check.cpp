// What it costs CGAL to check a pattern: the two-sided Hausdorff distance between an input mesh
// and a run's approximation.obj with CGAL::Polygon_mesh_processing::
// bounded_error_symmetric_Hausdorff_distance (the max of bounded_error_Hausdorff_distance in
// both directions), error bound a share of the input's bounding-box diagonal. bench/speed.sh
// sets a run's seconds against the seconds this prints.
//
//   build/bench/cgal_hausdorff_check INPUT APPROXIMATION.obj [--error-bound 1e-6]
//
// Prints one line: `hausdorff H bound B seconds S cpu C faces F1 F2 diagonal D` (H absolute, B
// the absolute error bound, S the wall seconds of the distance call alone, not of reading or
// repairing, C its processor seconds, which a busy machine inflates less; F1, F2 the triangles
// CGAL measured). Both files are read as polygon soups (any format CGAL
// reads: OFF, OBJ, PLY, STL), repaired and oriented so that CGAL can build a surface mesh (a
// non-manifold vertex is duplicated; the geometry stays the same), and triangulated. A soup
// that still is not a polygon mesh is measured as separate triangles. Exit status 1 when a file
// cannot be read, 2 for a bad command line.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

bool read_mesh(const std::string& path, SurfaceMesh& mesh) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, points, polygons) || polygons.empty()) return false;
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  if (PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  } else {
    for (const auto& polygon : polygons) {
      std::vector<SurfaceMesh::Vertex_index> corners;
      for (std::size_t index : polygon) corners.push_back(mesh.add_vertex(points[index]));
      mesh.add_face(corners);
    }
  }
  PMP::triangulate_faces(mesh);
  return !mesh.is_empty();
}

double diagonal(const SurfaceMesh& mesh) {
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
               dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  double share = 1e-6;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--error-bound" && i + 1 < argc) {
      share = std::atof(argv[++i]);
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "usage: cgal_hausdorff_check INPUT APPROXIMATION [--error-bound S]\n");
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.size() != 2 || !(share > 0.0)) {
    std::fprintf(stderr, "usage: cgal_hausdorff_check INPUT APPROXIMATION [--error-bound S]\n");
    return 2;
  }
  SurfaceMesh input, approximation;
  for (int k = 0; k < 2; ++k) {
    if (!read_mesh(files[k], k == 0 ? input : approximation)) {
      std::fprintf(stderr, "cgal_hausdorff_check: cannot read %s\n", files[k].c_str());
      return 1;
    }
  }
  const double diag = diagonal(input);
  const double bound = share * diag;
  const std::clock_t cpu_start = std::clock();
  const auto start = std::chrono::steady_clock::now();
  const double distance = PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
      input, approximation, bound);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  std::printf("hausdorff %.9g bound %.6g seconds %.6f cpu %.6f faces %zu %zu diagonal %.9g\n",
              distance, bound, seconds, cpu, static_cast<std::size_t>(input.number_of_faces()),
              static_cast<std::size_t>(approximation.number_of_faces()), diag);
  return 0;
}
