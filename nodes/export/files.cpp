#include "nodes/export/files.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/bvh.h"
#include "core/seams.h"

namespace papercraft {

namespace {

void append_number(std::string& out, double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  out += buffer;
}

const char* kind_name(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::Cut:
      return "cut";
    case EdgeKind::Seam:
      return "seam";
    case EdgeKind::Open:
      return "open";
  }
  return "cut";
}

}  // namespace

std::string approximation_obj(const std::vector<const RuledStrip*>& strips) {
  std::string out = "# papercraft approximation: one group per 3D strip\n";
  std::size_t base = 1;
  for (std::size_t s = 0; s < strips.size(); ++s) {
    const TriangleMesh& mesh = strips[s]->mesh;
    out += "g strip_" + std::to_string(s) + "\n";
    for (const Vec3& p : mesh.vertices) {
      out += "v ";
      append_number(out, p.x());
      out += ' ';
      append_number(out, p.y());
      out += ' ';
      append_number(out, p.z());
      out += '\n';
    }
    for (const Triangle& t : mesh.triangles) {
      // Two corners at one point (a fan's apex on its own polyline): no surface, no face.
      const auto& v = mesh.vertices;
      if (v[t[0]] == v[t[1]] || v[t[1]] == v[t[2]] || v[t[2]] == v[t[0]]) continue;
      out += "f " + std::to_string(base + t[0]) + " " + std::to_string(base + t[1]) + " " +
             std::to_string(base + t[2]) + "\n";
    }
    base += mesh.vertices.size();
  }
  return out;
}

std::string strips_json(const std::vector<FlatStrip>& strips) {
  nlohmann::json root;
  root["strips"] = nlohmann::json::array();
  for (const FlatStrip& strip : strips) {
    nlohmann::json s;
    s["id"] = strip.id;
    s["source_strip"] = strip.source_strip;
    s["vertices3d"] = nlohmann::json::array();
    for (const Vec3& p : strip.vertices3d) s["vertices3d"].push_back({p.x(), p.y(), p.z()});
    s["vertices2d"] = nlohmann::json::array();
    for (const Vec2& p : strip.vertices2d) s["vertices2d"].push_back({p.x(), p.y()});
    s["triangles"] = nlohmann::json::array();
    for (const Triangle& t : strip.triangles) s["triangles"].push_back({t[0], t[1], t[2]});
    if (!strip.uvs.empty()) {
      s["uv"] = nlohmann::json::array();
      for (const Vec2& p : strip.uvs) s["uv"].push_back({p.x(), p.y()});
    }
    s["boundary"] = nlohmann::json::array();
    for (const BoundaryEdge& e : strip.boundary) {
      nlohmann::json edge = {{"v0", e.v0}, {"v1", e.v1}, {"kind", kind_name(e.kind)}};
      if (e.kind == EdgeKind::Seam) {
        edge["neighbour"] = e.neighbour_strip;
        edge["partner_edge"] = e.partner_edge;
        edge["label"] = e.label;
      }
      s["boundary"].push_back(std::move(edge));
    }
    root["strips"].push_back(std::move(s));
  }
  // Each seam once, with its chain of boundary edges on both sides (the same strip twice for
  // the ruling a closed strip was opened along), so other tools can check that they meet.
  root["seams"] = nlohmann::json::array();
  for (const SeamChain& chain : labelled_chains(strips)) {
    nlohmann::json sides = nlohmann::json::array();
    for (const SeamSide& side : chain.sides)
      sides.push_back({{"strip", side.strip}, {"edges", side.edges}});
    root["seams"].push_back({{"label", chain.label},
                             {"self", chain.sides[0].strip == chain.sides[1].strip},
                             {"sides", std::move(sides)}});
  }
  return root.dump(1) + "\n";
}

namespace {

// A piece's page transform: strip vertices2d -> page mm.
nlohmann::json transform_json(const PageTransform& t) {
  return {{"linear", {t.linear(0, 0), t.linear(0, 1), t.linear(1, 0), t.linear(1, 1)}},
          {"translation", {t.translation.x(), t.translation.y()}},
          {"rotation_degrees", t.rotation_degrees}};
}

}  // namespace

std::string pieces_json(const PatternLayout& layout, const BuildOrder& order) {
  nlohmann::json pieces = nlohmann::json::array();
  for (std::size_t page = 0; page < layout.pages.size(); ++page) {
    for (const PlacedPiece& piece : layout.pages[page].pieces) {
      nlohmann::json seams = nlohmann::json::array();
      for (const PieceSeam& seam : piece.seams)
        seams.push_back({{"label", seam.label}, {"partner", seam.partner}, {"tab", seam.tab}});
      nlohmann::json entry = {{"name", piece.name},
                              {"strip", piece.strip_id},
                              {"piece_index", piece.piece_index},
                              {"piece_count", piece.piece_count},
                              {"page", page + 1},
                              {"transform", transform_json(piece.transform)},
                              {"seams", std::move(seams)}};
      if (const BuildStep* step = order.step_of(piece.name)) {
        nlohmann::json glue = nlohmann::json::array();
        for (const GlueSeam& seam : step->seams)
          glue.push_back({{"label", seam.label},
                          {"partner", seam.partner},
                          {"length_mm", std::round(seam.length_mm * 100.0) / 100.0},
                          {"closes_loop", seam.closes_loop}});
        entry["step"] = step->step;
        entry["part"] = step->part;
        entry["glue_to"] = step->attach_to;
        entry["glue"] = std::move(glue);
      }
      pieces.push_back(std::move(entry));
    }
  }
  nlohmann::json joints = nlohmann::json::array();
  for (std::size_t page = 0; page < layout.pages.size(); ++page) {
    for (const PlacedPiece& joint : layout.pages[page].joints) {
      joints.push_back({{"seam", joint.name},
                        {"page", page + 1},
                        {"transform", transform_json(joint.transform)},
                        {"outline", joint.vertices}});
    }
  }
  // In number order (1, 2, ..., 12a, 12b, ...), whatever page each lies on.
  std::stable_sort(pieces.begin(), pieces.end(), [](const auto& a, const auto& b) {
    return piece_name_less(a.at("name").template get<std::string>(),
                           b.at("name").template get<std::string>());
  });
  nlohmann::json root = {
      {"mm_per_unit", layout.mm_per_unit},
      {"page", {{"width_mm", layout.page.width_mm}, {"height_mm", layout.page.height_mm}}},
      {"pages", layout.pages.size()},
      {"parts", order.parts},
      {"pieces", std::move(pieces)},
      {"joints", std::move(joints)}};
  return root.dump(1) + "\n";
}

std::vector<double> vertex_distances(const Mesh& mesh, const TriangleMesh& to) {
  std::vector<double> distances(mesh.n_vertices(), 0.0);
  if (to.empty()) return distances;
  const TriangleBvh bvh(to);
  for (auto v : mesh.vertices()) distances[v.idx()] = bvh.closest(to_eigen(mesh.point(v))).distance;
  return distances;
}

std::string error_ply(const Mesh& mesh, const std::vector<double>& distances, double red_at) {
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\ncomment papercraft error map: distance to the approximation\n"
      << "element vertex " << mesh.n_vertices()
      << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "property double quality\nelement face " << mesh.n_faces()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  out.precision(17);
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const double d = distances[v.idx()];
    const double t = red_at > 0 ? std::clamp(d / red_at, 0.0, 1.0) : 0.0;
    // green -> blue -> red, as the paper's error maps
    const double r = t < 0.5 ? 0.0 : (t - 0.5) * 2.0;
    const double g = t < 0.5 ? 1.0 - 2.0 * t : 0.0;
    const double b = t < 0.5 ? 2.0 * t : 1.0 - (t - 0.5) * 2.0;
    out << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << static_cast<int>(255 * r + 0.5) << ' '
        << static_cast<int>(255 * g + 0.5) << ' ' << static_cast<int>(255 * b + 0.5) << ' ' << d
        << '\n';
  }
  for (auto f : mesh.faces()) {
    out << 3;
    for (auto v : f.vertices()) out << ' ' << v.idx();
    out << '\n';
  }
  return out.str();
}

}  // namespace papercraft
