// load.openmesh — read OBJ/OFF/PLY/STL with OpenMesh's readers, validate, repair what is
// safe. The framework fixes the model's absolute tolerance from the loaded bounding box.
//
//   load: {impl: load.openmesh, params: {repair: true}, to: [segment]}

#include <spdlog/spdlog.h>

#include "core/errors.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "nodes/load/openmesh.h"

namespace papercraft {

MeshSummary summarize(const Mesh& mesh, bool has_uvs) {
  MeshSummary s;
  s.vertices = mesh.n_vertices();
  s.faces = mesh.n_faces();
  const TriangleMesh triangles = to_triangle_mesh(mesh);
  if (!triangles.vertices.empty()) {
    const auto box = bounding_box(triangles.vertices);
    s.box_min = box[0];
    s.box_max = box[1];
    s.largest_side = (box[1] - box[0]).maxCoeff();
    s.area = surface_area(triangles);
  }
  s.boundary_loops = static_cast<int>(boundary_loops(mesh).size());
  s.components = connected_components(mesh);
  s.euler_characteristic = euler_characteristic(mesh);
  s.has_uvs = has_uvs;
  return s;
}

void register_load_openmesh(Registry& registry) {
  using O = LoadOptions;
  static const auto table =
      ParamTable<O>()
          .add(
              "repair", [](O & o) -> auto& { return o.repair; },
              "the safe repairs, each logged: remove unreferenced vertices, merge exactly "
              "duplicate vertices, heal zero-area faces, remove duplicate faces (keep one side "
              "of a two-sided surface), cut non-manifold edges apart, split non-manifold "
              "vertices, orient the faces consistently (false: none is made; the faces they "
              "would heal or remove, non-manifold edges and vertices and an inconsistent "
              "orientation are errors)")
          .add(
              "max_faces", [](O & o) -> auto& { return o.max_faces; }, "refuse larger meshes",
              at_least(1));
  registry.add(
      {.name = "load.openmesh",
       .summary = "read OBJ/OFF/PLY/STL (ascii and binary) with OpenMesh, validate",
       .input = MessageType::of<Job>(),
       .outputs = {{"out", MessageType::of<Model>()}},
       .params = table.specs(),
       .create = [](const Params& params, const NodeContext&) {
         const LoadOptions options = table.read(params);
         return make_body([options](const Envelope& in, Emitter& out) {
           const Job& job = in.get<Job>();
           LoadedMesh loaded = job.mesh ? load_arrays(*job.mesh, job.input.string(), options)
                                        : load_mesh(job.input, options);
           for (const auto& repair : loaded.repairs) {
             spdlog::warn("{}: {}", job.input.string(), repair);
             in.model->note(repair);
           }
           Model model;
           model.summary = summarize(loaded.mesh, loaded.has_uvs);
           if (!(model.summary.largest_side > 0)) {
             throw InvalidInputException(job.input.string() +
                                         ": all vertices coincide (the bounding box is a point)");
           }
           model.texture_path = loaded.texture_path;
           model.appearance =
               std::make_shared<const SurfaceAppearance>(std::move(loaded.appearance));
           model.mesh = std::make_shared<const Mesh>(std::move(loaded.mesh));
           out.emit("out", std::move(model));
         });
       }});
}

}  // namespace papercraft
