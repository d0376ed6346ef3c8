// layout.pages — scale the flat strips to real size and pack them onto pages with tabs,
// labels, fold lines and a scale bar.
//
//   layout: {impl: layout.pages, params: {page: A4, margin_mm: 10}, to: [export]}

#include "core/errors.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/registry.h"
#include "nodes/layout/pages.h"

namespace papercraft {

void register_layout_pages(Registry& registry) {
  registry.add(
      {"layout.pages",
       "real-world scale, tightest rotation, MaxRects packing onto pages",
       MessageType::of<ModelStrips>(),
       false,
       {{"out", MessageType::of<Pattern>()}},
       {{"page", ParamType::String, "A4", "A4, A3, Letter or WIDTHxHEIGHT in mm (e.g. 300x450)"},
        {"margin_mm", ParamType::Number, "10", "blank border on every side of a page"},
        {"height_mm", ParamType::Number, "200",
         "size of the model's largest bounding-box side on paper (--height overrides)"},
        {"tab_width_mm", ParamType::Number, "5", "glue tab width (0: no tabs)"},
        {"fold_angle_degrees", ParamType::Number, "0.5",
         "inner edges bent more than this get a fold line"},
        {"strong_fold_angle_degrees", ParamType::Number, "10",
         "folds bent less than this are drawn as faint gentle-bend marks"},
        {"spacing_mm", ParamType::Number, "2", "gap between pieces"},
        {"packing", ParamType::String, "maxrects", "maxrects or shelf", {"maxrects", "shelf"}}},
       [](const Params& params) {
         LayoutOptions options;
         try {
           options.page = page_size_from_name(params.string("page"));
         } catch (const std::exception& e) {
           throw std::invalid_argument("page: " + std::string(e.what()));
         }
         options.margin_mm = params.number("margin_mm");
         options.height_mm = params.number("height_mm");
         options.tab_width_mm = params.number("tab_width_mm");
         options.fold_angle_degrees = params.number("fold_angle_degrees");
         options.strong_fold_angle_degrees = params.number("strong_fold_angle_degrees");
         options.spacing_mm = params.number("spacing_mm");
         options.packing =
             params.string("packing") == "shelf" ? PackingMethod::Shelf : PackingMethod::MaxRects;
         return make_body([options](const Envelope& in, Emitter& out) {
           auto strips = in.get_shared<ModelStrips>();
           LayoutOptions run_options = options;
           const RunSettings& settings = *in.model->settings;
           if (settings.height_mm > 0) run_options.height_mm = settings.height_mm;
           if (settings.scale > 0) run_options.scale = settings.scale;
           auto layout = std::make_shared<PatternLayout>(layout_pages(strips->flat, run_options));
           for (const auto& warning : layout->warnings) in.model->note(warning);
           in.model->set_result("pages", static_cast<double>(layout->pages.size()));
           in.model->set_result("shelf_pages", static_cast<double>(layout->shelf_page_count));
           in.model->set_result("mm_per_unit", layout->mm_per_unit);
           Pattern pattern;
           pattern.strips = strips;
           pattern.layout = layout;
           out.emit(0, std::move(pattern));
         });
       }});
}

}  // namespace papercraft
