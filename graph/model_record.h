#pragma once
// What one model produced, as typed fields: report.json, batch.json and the command's
// summary line read this record; each field names the stage that fills it.

#include <string>
#include <vector>

#include "core/effort.h"
#include "core/triangle_mesh.h"

namespace papercraft {

/// Facts about the input mesh, for report.json.
struct MeshSummary {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  Vec3 box_min = Vec3::Zero();
  Vec3 box_max = Vec3::Zero();
  double largest_side = 0.0;
  double area = 0.0;  // surface area, model units squared
  int boundary_loops = 0;
  int components = 0;
  int euler_characteristic = 0;
  bool has_uvs = false;
};

/// What the proxy stage did (report.json "proxy"). Without a proxy (proxy.none, or a mesh
/// already small for the tolerance) `used` is false and the strips are refined on the input.
struct ProxySummary {
  bool used = false;
  std::string method = "none";  // the proxy implementation: "none", "decimate"
  std::size_t vertices = 0;     // the proxy's (0 when not used)
  std::size_t faces = 0;
  double distance_bound = 0.0;  // certified upper bound of H(proxy, input); 0 when not used
  double seconds = 0.0;         // decimation and certification
  std::string reason;           // why no proxy is used, when none is
};

struct ModelRecord {
  /// The framework, when the loader emits the model: the input and the absolute tolerance
  /// (from the run's tolerance and the input's largest side).
  bool loaded = false;
  MeshSummary input;
  double tolerance = 0.0;

  int segments = 0;  // segment: parts emitted
  long cuts = 0;     // cut: rejected parts cut

  /// merge: the model's strips.
  int strips_3d = 0;
  int flat_strips_before_merge = 0;
  int flat_strips = 0;
  /// A certified upper bound of H(approximation, input): strips_bound plus the proxy's
  /// distance_bound (the Hausdorff distance obeys the triangle inequality).
  double hausdorff_bound = 0.0;
  double strips_bound = 0.0;  // the largest upper bound over the 3D strips, to what was refined
  bool certified = false;     // every strip's bound certified (none sampled), the proxy's too

  /// proxy: the simplified surface refined in place of the input.
  ProxySummary proxy;

  /// The framework, with the tolerance: mm on paper per model unit.
  double mm_per_unit = 0.0;

  /// layout: the pages.
  int pages = 0;
  int shelf_pages = 0;
  int rectangle_pages = 0;        // what the rectangle packer needs for the same pieces
  std::vector<double> page_fill;  // per page: pieces and tabs over the printable area
  int seams = 0;
  int seams_without_tab = 0;
  int joining_strips = 0;
  double smallest_text_mm = 0.0;
  int overlapping_text = 0;
  /// layout: what the pages cost a person to cut and glue (report.json "effort").
  AssemblyEffort effort;
  bool effort_measured = false;  // false until the layout ran

  /// export: the largest distance of an input vertex to the approximation (error.ply).
  double max_vertex_distance = 0.0;
  /// export: the print images baked from the input's textures or colours (report.json
  /// "texture"); 0 when nothing was baked.
  double bake_seconds = 0.0;
  /// CPU seconds of the bake summed over the threads that did it (what one thread would take
  /// on an idle machine; wall seconds also count waiting for a shared core).
  double bake_cpu_seconds = 0.0;
  long baked_pixels = 0;
  int baked_images = 0;

  /// Repairs made by the loader, warnings of any stage (report.json "notes").
  std::vector<std::string> notes;
};

}  // namespace papercraft
