// export.files — writes the per-model outputs of DESIGN.md section 4 into <out>/<name>/:
// report.json, approximation.obj, strips.json, pieces.json, error.ply, pattern.pdf,
// pattern-NN.svg, assembly.html. Every file is written to a temporary name and renamed into
// place.
//
//   export: {impl: export.files, params: {formats: [pdf, svg, obj, json, ply, html]}}

#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/build_order.h"
#include "core/printable_utf8.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/registry.h"
#include "nodes/export/assembly_html.h"
#include "nodes/export/bake.h"
#include "nodes/export/files.h"
#include "nodes/export/image.h"
#include "nodes/export/pdf.h"
#include "nodes/export/report_node.h"
#include "nodes/export/svg.h"

namespace papercraft {

namespace {

/// CPU time of the calling thread, in seconds.
double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

struct ExportOptions {
  std::vector<std::string> formats = {"pdf", "svg", "obj", "json", "ply", "html"};
  StyleOptions style;
  BakeOptions bake;
  long max_texture_pixels = 64'000'000;
  double html_max_mb = 5.0;
};

// The texture image of every material, read once; a missing or unreadable one (or one too
// large) is named with its material in the notes and on stderr, and left out.
std::vector<std::shared_ptr<const Image>> material_images(ModelRun& model,
                                                          const SurfaceAppearance& appearance,
                                                          long max_pixels) {
  std::vector<std::shared_ptr<const Image>> images(appearance.materials.size());
  for (std::size_t m = 0; m < appearance.materials.size(); ++m) {
    const Material& material = appearance.materials[m];
    if (material.texture.empty()) continue;
    try {
      images[m] = std::make_shared<const Image>(
          material.texture_bytes
              ? decode_image(material.texture, *material.texture_bytes, max_pixels)
              : load_image(material.texture, max_pixels));
    } catch (const std::exception& e) {
      const std::string text = "texture of material '" + printable_utf8(material.name) +
                               "' not printed: " + printable_utf8(e.what());
      model.note(text);
      spdlog::warn("{}: {}", printable_utf8(model.name), text);
    }
  }
  return images;
}

bool wants(const std::vector<std::string>& formats, const std::string& format) {
  return std::find(formats.begin(), formats.end(), format) != formats.end();
}

nlohmann::json vec3_json(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

// report.json's "effort": the total, each term, what each term costs and the weights.
nlohmann::json effort_json(const AssemblyEffort& effort) {
  const EffortTerms& t = effort.terms;
  const EffortWeights& w = effort.weights;
  return {{"total", effort.total},
          {"things_to_cut", t.things_to_cut},
          {"printed_pieces", t.printed_pieces},
          {"joining_strips", t.joining_strips},
          {"seam_chains", t.seam_chains},
          {"self_seams", t.self_seams},
          {"glue_length_mm", t.glue_length_mm},
          {"sawtooth_corners", t.sawtooth_corners},
          {"small_pieces", t.small_pieces},
          {"narrow_pieces", t.narrow_pieces},
          {"cost",
           {{"things_to_cut", w.piece * t.things_to_cut},
            {"seam_chains", w.seam * t.seam_chains},
            {"glue_length", w.glue_per_metre * t.glue_length_mm / 1000.0},
            {"sawtooth_corners", w.sawtooth * t.sawtooth_corners},
            {"small_pieces", w.small_piece * t.small_pieces},
            {"narrow_pieces", w.narrow_piece * t.narrow_pieces}}},
          {"weights",
           {{"piece", w.piece},
            {"seam", w.seam},
            {"glue_per_metre", w.glue_per_metre},
            {"sawtooth", w.sawtooth},
            {"small_piece", w.small_piece},
            {"narrow_piece", w.narrow_piece}}}};
}

}  // namespace

nlohmann::json model_report(const ModelRun& model) {
  const ModelRecord record = model.record();
  nlohmann::json report;
  report["version"] = PAPERCRAFT_VERSION;
  // A file's name may be any bytes; JSON takes UTF-8 only.
  nlohmann::json input = {{"path", printable_utf8(model.input_path.string())},
                          {"name", printable_utf8(model.name)}};
  if (record.loaded) {
    const MeshSummary& s = record.input;
    input["vertices"] = s.vertices;
    input["faces"] = s.faces;
    input["bounding_box"] = {{"min", vec3_json(s.box_min)}, {"max", vec3_json(s.box_max)}};
    input["largest_side"] = s.largest_side;
    input["boundary_loops"] = s.boundary_loops;
    input["components"] = s.components;
    input["euler_characteristic"] = s.euler_characteristic;
    input["has_uvs"] = s.has_uvs;
  }
  report["input"] = input;
  const ToleranceSpec& spec = model.settings->tolerance;
  const double largest = record.input.largest_side;
  report["tolerance"] = {
      {"given", spec.to_string()},
      {"absolute", record.tolerance},
      {"relative_percent", largest > 0 ? 100.0 * record.tolerance / largest : 0.0}};
  const PaperSpec& paper = model.settings->paper;
  report["paper"] = {{"mm_per_unit", record.mm_per_unit},
                     {"height_mm", record.mm_per_unit * largest},
                     {"min_width_mm", paper.min_width_mm},
                     {"min_area_mm2", paper.min_area_mm2}};
  report["result"] = {
      {"certified", record.certified},
      {"hausdorff_bound", record.hausdorff_bound},
      {"hausdorff_bound_percent", largest > 0 ? 100.0 * record.hausdorff_bound / largest : 0.0},
      {"strips_bound", record.strips_bound},
      {"strips_3d", record.strips_3d},
      {"flat_strips_before_merge", record.flat_strips_before_merge},
      {"flat_strips", record.flat_strips},
      {"pages", record.pages},
      {"shelf_pages", record.shelf_pages},
      {"segments", record.segments},
      {"cuts", record.cuts},
      {"mm_per_unit", record.mm_per_unit}};
  const ProxySummary& proxy = record.proxy;
  report["proxy"] = {{"method", proxy.method},
                     {"used", proxy.used},
                     {"vertices", proxy.vertices},
                     {"faces", proxy.faces},
                     {"distance_bound", proxy.distance_bound},
                     {"refinement_tolerance", record.tolerance - proxy.distance_bound},
                     {"seconds", proxy.seconds},
                     {"reason", proxy.reason}};
  double fill_but_last = 0.0;
  for (std::size_t i = 0; i + 1 < record.page_fill.size(); ++i)
    fill_but_last += record.page_fill[i];
  if (record.page_fill.size() > 1)
    fill_but_last /= static_cast<double>(record.page_fill.size() - 1);
  report["layout"] = {{"pages", record.pages},
                      {"rectangle_pages", record.rectangle_pages},
                      {"page_fill", record.page_fill},
                      {"mean_fill_but_last", fill_but_last},
                      {"seams", record.seams},
                      {"seams_without_tab", record.seams_without_tab},
                      {"joining_strips", record.joining_strips},
                      {"smallest_text_mm", record.smallest_text_mm},
                      {"overlapping_text", record.overlapping_text}};
  if (record.effort_measured) report["effort"] = effort_json(record.effort);
  report["texture"] = {{"baked_images", record.baked_images},
                       {"baked_pixels", record.baked_pixels},
                       {"bake_seconds", record.bake_seconds},
                       {"bake_cpu_seconds", record.bake_cpu_seconds}};
  nlohmann::json nodes = nlohmann::json::object();
  for (std::size_t i = 0; i < model.node_labels.size(); ++i) {
    nodes[model.node_labels[i].first] = {
        {"impl", model.node_labels[i].second},
        {"calls", model.node_stats[i].calls.load()},
        {"seconds", model.node_stats[i].nanoseconds.load() * 1e-9}};
  }
  report["timing"] = {{"total_seconds", model.seconds()}, {"nodes", nodes}};
  report["threads"] = model.settings->threads;
  report["config"] = {{"file", printable_utf8(model.settings->config_file)},
                      {"text", printable_utf8(model.settings->config_text)}};
  report["notes"] = record.notes;
  return report;
}

void register_export_files(Registry& registry) {
  using O = ExportOptions;
  static const auto table =
      ParamTable<O>()
          .add("formats", [](O & o) -> auto& { return o.formats; },
               "which files to write besides report.json", {},
               {"pdf", "svg", "obj", "json", "ply", "html"})
          .add(
              "texture_dpi", [](O & o) -> auto& { return o.bake.dpi; },
              "resolution of the pieces' print images baked from the input's textures or colours",
              between(10, 1200))
          .add(
              "bleed_mm", [](O & o) -> auto& { return o.bake.bleed_mm; },
              "the print image reaches this far beyond the cut line", between(0, 10))
          .add(
              "tab_texture", [](O & o) -> auto& { return o.bake.tab_texture; },
              "tabs print the partner piece's surface across the seam (false: blank)")
          .add(
              "max_texture_pixels", [](O & o) -> auto& { return o.max_texture_pixels; },
              "a texture image with more pixels is refused, not read", at_least(1))
          .add(
              "html_max_mb", [](O & o) -> auto& { return o.html_max_mb; },
              "assembly.html stays under this size (MB): print images, then pages, are left out",
              greater_than(0))
          .choice(
              "preset", [](O & o) -> auto& { return o.style.preset; },
              std::vector<std::pair<std::string, StylePreset>>{{"print", StylePreset::Print},
                                                               {"laser", StylePreset::Laser},
                                                               {"cutter", StylePreset::Cutter}},
              "colours and line styles: print, laser (cut red, score blue) or cutter");
  registry.add(
      {.name = "export.files",
       .summary = "report.json, approximation.obj, strips.json, pieces.json, error.ply, PDF, SVG "
                  "and assembly.html",
       .input = MessageType::of<Pattern>(),
       .params = table.specs(),
       .create = [](const Params& params, const NodeContext&) {
         const ExportOptions options = table.read(params);
         const std::vector<std::string>& formats = options.formats;
         const StyleOptions& style = options.style;
         const BakeOptions bake = options.bake;
         const long max_texture_pixels = options.max_texture_pixels;
         AssemblyHtmlOptions html;
         html.max_bytes = static_cast<std::size_t>(options.html_max_mb * 1e6);
         return make_body([formats, style, bake, max_texture_pixels, html](const Envelope& in,
                                                                           Emitter&) {
           const Pattern& pattern = in.get<Pattern>();
           const ModelStrips& strips = *pattern.strips;
           ModelRun& model = *in.model;
           if (wants(formats, "obj")) {
             std::vector<const RuledStrip*> strips3d;
             for (const auto& s : strips.strips3d) strips3d.push_back(s->strip.get());
             model.write_file("approximation.obj", approximation_obj(strips3d));
           }
           if (wants(formats, "json")) model.write_file("strips.json", strips_json(strips.flat));
           if (wants(formats, "ply") && strips.model) {
             TriangleMesh all;
             for (const auto& s : strips.strips3d) {
               const int base = static_cast<int>(all.vertices.size());
               all.vertices.insert(all.vertices.end(), s->strip->mesh.vertices.begin(),
                                   s->strip->mesh.vertices.end());
               for (const Triangle& t : s->strip->mesh.triangles) {
                 all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
               }
             }
             const auto distances = vertex_distances(*strips.model->mesh, all);
             double worst = 0.0;
             for (double d : distances) worst = std::max(worst, d);
             model.update([worst](ModelRecord& record) { record.max_vertex_distance = worst; });
             model.write_file("error.ply",
                              error_ply(*strips.model->mesh, distances, model.tolerance()));
           }
           if (pattern.layout) {
             const PatternLayout& layout = *pattern.layout;
             StyleOptions page_style = style;
             page_style.title = printable_utf8(model.name);  // cairo and SVG: UTF-8
             // The print images, baked from the input surface when it has textures or colours.
             std::vector<std::vector<BakedImage>> images;
             if (strips.model && strips.model->appearance && !strips.model->appearance->empty() &&
                 (wants(formats, "pdf") || wants(formats, "svg") || wants(formats, "html"))) {
               const auto start = std::chrono::steady_clock::now();
               const double sampler_cpu_start = thread_cpu_seconds();
               const SurfaceSampler sampler(
                   *strips.model->mesh, *strips.model->appearance,
                   material_images(model, *strips.model->appearance, max_texture_pixels));
               if (!sampler.empty()) {
                 std::map<int, const FlatStrip*> by_id;
                 for (const FlatStrip& strip : strips.flat) by_id[strip.id] = &strip;
                 images.resize(layout.pages.size());
                 std::atomic<double> cpu{thread_cpu_seconds() - sampler_cpu_start};
                 tbb::parallel_for(std::size_t{0}, layout.pages.size(), [&](std::size_t page) {
                   const double cpu_start = thread_cpu_seconds();
                   images[page] = bake_page(layout.pages[page], by_id, sampler, bake);
                   cpu.fetch_add(thread_cpu_seconds() - cpu_start);
                 });
                 page_style.images = &images;
                 long pixels = 0;
                 int count = 0;
                 for (const auto& page : images)
                   for (const BakedImage& image : page) {
                     pixels += static_cast<long>(image.width) * image.height;
                     ++count;
                   }
                 const double seconds =
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                         .count();
                 const double cpu_seconds = cpu.load();
                 model.update([=](ModelRecord& record) {
                   record.bake_seconds = seconds;
                   record.bake_cpu_seconds = cpu_seconds;
                   record.baked_pixels = pixels;
                   record.baked_images = count;
                 });
               }
             }
             const BuildOrder order = build_order(layout);
             if (wants(formats, "json")) model.write_file("pieces.json", pieces_json(layout, order));
             if (wants(formats, "svg")) {
               for (std::size_t page = 0; page < layout.pages.size(); ++page) {
                 const std::string number = std::to_string(page + 1);
                 const std::string name =
                     "pattern-" + std::string(number.size() < 2 ? 1 : 0, '0') + number + ".svg";
                 model.write_file(name,
                                  pattern_page_svg(layout, static_cast<int>(page), page_style));
               }
             }
             if (wants(formats, "pdf")) {
               Guide guide{guide_pieces(layout, strips.flat), {}};
               for (const BuildStep& step : order.steps)
                 guide.steps.push_back(build_step_text(step));
               model.write_file("pattern.pdf", [&](std::ostream& out) {
                 write_pattern_pdf(layout, out, page_style, &guide);
               });
               if (!layout.pages.empty())
                 model.write_file("guide.png", guide_png(guide, layout.page, model.name));
             }
             if (wants(formats, "html")) {
               const AssemblyHtml page =
                   assembly_html(layout, strips.flat, order, page_style, html);
               for (const std::string& note : page.notes) model.note("assembly.html: " + note);
               model.write_file("assembly.html", page.text);
             }
           }
           model.write_file("report.json", model_report(model).dump(2) + "\n");
         });
       }});
}

}  // namespace papercraft
