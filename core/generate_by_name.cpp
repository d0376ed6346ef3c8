// The shapes by name: their parameters (the fields of each Options struct, same names and
// defaults), for `papercraft generate` and the tests.

#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "core/errors.h"
#include "core/generate.h"

namespace papercraft {
namespace {

std::string format_number(double value) {
  std::ostringstream stream;
  stream << value;
  return stream.str();
}

template <class Options>
struct OptionField {
  const char* name;
  std::variant<double Options::*, int Options::*> member;
  const char* description;
};

struct ShapeEntry {
  std::string name;
  std::string description;
  std::vector<ShapeParameter> parameters;
  std::function<TriangleMesh(const std::map<std::string, double>&)> generate;
};

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

template <class Options>
ShapeEntry make_entry(std::string name, std::string description,
                      std::vector<OptionField<Options>> fields,
                      TriangleMesh (*generator)(const Options&)) {
  ShapeEntry entry;
  entry.name = name;
  entry.description = std::move(description);
  const Options defaults{};
  std::vector<std::string> known;
  for (const auto& field : fields) {
    const double value = std::visit(
        [&](auto member) { return static_cast<double>(defaults.*member); }, field.member);
    entry.parameters.push_back({field.name, value, field.description});
    known.push_back(field.name);
  }
  entry.generate = [name, fields, generator, known](const std::map<std::string, double>& values) {
    Options options{};
    for (const auto& assignment : values) {
      // Named references, not a structured binding: clang before 16 cannot capture one.
      const std::string& key = assignment.first;
      const double value = assignment.second;
      auto field = std::find_if(fields.begin(), fields.end(),
                                [&](const OptionField<Options>& f) { return key == f.name; });
      if (field == fields.end()) {
        throw InvalidInputException("shape '" + name + "' has no parameter '" + key +
                                    "'; its parameters are: " + join(known));
      }
      std::visit(
          [&](auto member) {
            using Field = std::remove_reference_t<decltype(options.*member)>;
            if constexpr (std::is_same_v<Field, int>) {
              if (!std::isfinite(value) || value != std::floor(value) ||
                  std::abs(value) > std::numeric_limits<int>::max()) {
                throw InvalidInputException("shape '" + name + "': parameter '" + key +
                                            "' must be an integer (got " + format_number(value) +
                                            ")");
              }
              options.*member = static_cast<int>(value);
            } else {
              options.*member = value;
            }
          },
          field->member);
    }
    return generator(options);
  };
  return entry;
}

const std::vector<ShapeEntry>& shape_table() {
  using Cyl = OpenCylinderOptions;
  using Ell = EllipticCylinderOptions;
  using Cone = ConeFrustumOptions;
  using Fig = FigureEightOptions;
  using Holes = CylinderTwoHolesOptions;
  using Capped = CappedCylinderOptions;
  using Bell = DumbbellOptions;
  static const std::vector<ShapeEntry> table = {
      make_entry<Cyl>("open_cylinder", "cylinder without caps (2 boundary loops)",
                      {{"radius", &Cyl::radius, "radius"},
                       {"height", &Cyl::height, "length along the z axis"},
                       {"segments", &Cyl::segments, "vertices around each circle (integer >= 3)"},
                       {"rings", &Cyl::rings, "bands of quads along the axis (integer >= 1)"}},
                      &open_cylinder),
      make_entry<Ell>("elliptic_cylinder", "open cylinder over an ellipse (2 boundary loops)",
                      {{"semi_axis_x", &Ell::semi_axis_x, "semi-axis along x"},
                       {"semi_axis_y", &Ell::semi_axis_y, "semi-axis along y"},
                       {"height", &Ell::height, "length along the z axis"},
                       {"segments", &Ell::segments, "vertices around the ellipse (integer >= 3)"},
                       {"rings", &Ell::rings, "bands of quads along the axis (integer >= 1)"}},
                      &elliptic_cylinder),
      make_entry<Cone>("cone_frustum", "open truncated cone (2 boundary loops)",
                       {{"bottom_radius", &Cone::bottom_radius, "radius at z = -height/2"},
                        {"top_radius", &Cone::top_radius, "radius at z = +height/2"},
                        {"height", &Cone::height, "length along the z axis"},
                        {"segments", &Cone::segments, "vertices around each circle (integer >= 3)"},
                        {"rings", &Cone::rings, "bands of quads along the axis (integer >= 1)"}},
                       &cone_frustum),
      make_entry<SphereOptions>(
          "sphere", "icosphere (closed, genus 0)",
          {{"radius", &SphereOptions::radius, "radius"},
           {"subdivisions", &SphereOptions::subdivisions,
            "subdivisions of the icosahedron (integer 0..8); faces = 20 * 4^subdivisions"}},
          &sphere),
      make_entry<TorusOptions>(
          "torus", "torus around the z axis (closed, genus 1)",
          {{"major_radius", &TorusOptions::major_radius,
            "distance from the axis to the tube centre"},
           {"minor_radius", &TorusOptions::minor_radius, "tube radius (< major_radius)"},
           {"segments", &TorusOptions::segments, "vertices around the z axis (integer >= 3)"},
           {"tube_segments", &TorusOptions::tube_segments,
            "vertices around the tube (integer >= 3)"}},
          &torus),
      make_entry<Fig>(
          "figure_eight", "two fused tori, marching tetrahedra (closed, genus 2)",
          {{"major_radius", &Fig::major_radius, "major radius of each torus"},
           {"minor_radius", &Fig::minor_radius, "tube radius of each torus (<= major_radius/2)"},
           {"blend", &Fig::blend, "smooth-union radius at the junction (0..minor_radius)"},
           {"resolution", &Fig::resolution,
            "grid cells along x (integer; cell size <= minor_radius/2)"}},
          &figure_eight),
      make_entry<PawnOptions>(
          "pawn", "chess pawn, surface of revolution (closed, genus 0)",
          {{"height", &PawnOptions::height, "total height (base radius is 0.36 * height)"},
           {"segments", &PawnOptions::segments, "vertices around the z axis (integer >= 3)"},
           {"profile_samples", &PawnOptions::profile_samples,
            "profile points between the poles (integer >= 7)"}},
          &pawn),
      make_entry<Holes>(
          "cylinder_two_holes", "open cylinder with two rectangular holes (4 boundary loops)",
          {{"radius", &Holes::radius, "radius"},
           {"height", &Holes::height, "length along the z axis"},
           {"segments", &Holes::segments, "vertices around each circle (integer >= 6)"},
           {"rings", &Holes::rings, "bands of quads along the axis (integer >= 3)"},
           {"hole_segments", &Holes::hole_segments,
            "quads removed around the axis per hole (integer 1..segments/2-1)"},
           {"hole_rings", &Holes::hole_rings,
            "quads removed along the axis per hole (integer 1..rings-2)"}},
          &cylinder_two_holes),
      make_entry<BoxOptions>(
          "box", "closed box with gridded faces and sharp creases (genus 0)",
          {{"size_x", &BoxOptions::size_x, "extent along x"},
           {"size_y", &BoxOptions::size_y, "extent along y"},
           {"size_z", &BoxOptions::size_z, "extent along z"},
           {"divisions_x", &BoxOptions::divisions_x, "grid cells along x (integer >= 1)"},
           {"divisions_y", &BoxOptions::divisions_y, "grid cells along y (integer >= 1)"},
           {"divisions_z", &BoxOptions::divisions_z, "grid cells along z (integer >= 1)"}},
          &box),
      make_entry<Capped>(
          "capped_cylinder", "cylinder closed by two flat discs (closed, genus 0)",
          {{"radius", &Capped::radius, "radius"},
           {"height", &Capped::height, "length along the z axis"},
           {"segments", &Capped::segments, "vertices around each circle (integer >= 3)"},
           {"rings", &Capped::rings, "bands of quads along the side (integer >= 1)"},
           {"cap_rings", &Capped::cap_rings, "concentric bands on each disc (integer >= 1)"}},
          &capped_cylinder),
      make_entry<Bell>(
          "dumbbell", "two spheres joined by a bar, surface of revolution (closed, genus 0)",
          {{"sphere_radius", &Bell::sphere_radius, "radius of each sphere"},
           {"handle_radius", &Bell::handle_radius, "radius of the bar (< sphere_radius)"},
           {"handle_length", &Bell::handle_length, "length of the bar between the spheres"},
           {"segments", &Bell::segments, "vertices around the z axis (integer >= 3)"},
           {"sphere_rings", &Bell::sphere_rings, "profile bands on each sphere (integer >= 2)"},
           {"handle_rings", &Bell::handle_rings, "profile bands along the bar (integer >= 1)"}},
          &dumbbell),
  };
  return table;
}

const ShapeEntry& find_shape(const std::string& name) {
  for (const ShapeEntry& entry : shape_table()) {
    if (entry.name == name) return entry;
  }
  throw InvalidInputException("unknown shape '" + name + "'; known shapes: " + join(shape_names()));
}

}  // namespace

std::vector<std::string> shape_names() {
  std::vector<std::string> names;
  for (const ShapeEntry& entry : shape_table()) names.push_back(entry.name);
  return names;
}

std::string shape_description(const std::string& name) {
  return find_shape(name).description;
}

std::vector<ShapeParameter> shape_parameters(const std::string& name) {
  return find_shape(name).parameters;
}

TriangleMesh generate_shape(const std::string& name,
                            const std::map<std::string, double>& parameters) {
  return find_shape(name).generate(parameters);
}

}  // namespace papercraft
