// layout.pages — scale the flat strips to real size and pack them onto pages with tabs,
// labels, fold lines and a scale bar.
//
//   layout: {impl: layout.pages, params: {page: A4, margin_mm: 10}, to: [export]}

#include "core/effort.h"
#include "core/errors.h"
#include "core/page_size.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/registry.h"
#include "nodes/layout/pages.h"

namespace papercraft {

namespace {

PageSize page_of(const ParamValue& value) {
  try {
    return page_size_from_name(std::get<std::string>(value));
  } catch (const InvalidInputException& e) {
    throw std::invalid_argument(e.what());
  }
}

// layout.rectangles' options: the same, packed by rectangles unless told otherwise.
struct RectangleLayoutOptions : LayoutOptions {
  RectangleLayoutOptions() { packing = PackingMethod::MaxRects; }
};

template <class O>
ParamTable<O> layout_table(bool nesting) {
  auto table =
      ParamTable<O>()
          .convert(
              "page", ParamType::String, [](O & o) -> auto& { return o.page; }, page_size_name,
              page_of, "A3, A4, A5, Letter, Legal, Tabloid or WIDTHxHEIGHT in mm (e.g. 300x450)")
          .add(
              "margin_mm", [](O & o) -> auto& { return o.margin_mm; },
              "blank border on every side of a page", at_least(0))
          .add(
              "tab_width_mm", [](O & o) -> auto& { return o.tab_width_mm; },
              "glue tab width (0: no tabs); a tab narrows where its piece leaves less room",
              at_least(0))
          .add(
              "tab_angle_degrees", [](O & o) -> auto& { return o.tab_angle_degrees; },
              "angle between a tab's ends and its seam (90: rectangular tabs)",
              ParamRange{0.0, 90.0, true, false})
          .choice(
              "tab_style", [](O & o) -> auto& { return o.tab_style; },
              std::vector<std::pair<std::string, TabStyle>>{{"one", TabStyle::One},
                                                            {"alternate", TabStyle::Alternate},
                                                            {"both", TabStyle::Both},
                                                            {"none", TabStyle::None}},
              "one (one side of each seam), alternate (sides alternate along a seam every "
              "alternate_run_mm), both (each side; the partner glues over it) or none (no tabs)")
          .add(
              "alternate_run_mm", [](O & o) -> auto& { return o.alternate_run_mm; },
              "tab_style alternate: length of the runs whose tabs change sides along a seam",
              greater_than(0))
          .choice(
              "print_side", [](O & o) -> auto& { return o.print_side; },
              std::vector<std::pair<std::string, PrintSide>>{{"front", PrintSide::Front},
                                                             {"back", PrintSide::Back}},
              "front, or back: pages mirrored to print and cut on the back of the sheet (the "
              "print inside the model; mountain and valley swapped)")
          .add(
              "joining_strips", [](O & o) -> auto& { return o.joining_strips; },
              "a seam with room for a tab on neither side gets a loose strip glued behind both "
              "sides")
          .add(
              "label_size_mm", [](O & o) -> auto& { return o.label_size_mm; },
              "seam label text height", greater_than(0))
          .add(
              "number_size_mm", [](O & o) -> auto& { return o.number_size_mm; },
              "piece number text height (smaller on thin pieces, not below min_text_mm)",
              greater_than(0))
          .add(
              "min_text_mm", [](O & o) -> auto& { return o.min_text_mm; },
              "no label or number is printed smaller", greater_than(0))
          .add(
              "alignment_mark_mm", [](O & o) -> auto& { return o.alignment_mark_mm; },
              "tick printed across the cut line where two seams meet, on both pieces (0: none)",
              at_least(0))
          .add(
              "fold_angle_degrees", [](O & o) -> auto& { return o.fold_angle_degrees; },
              "inner edges bent more than this get a fold line", between(0, 180))
          .add(
              "strong_fold_angle_degrees",
              [](O & o) -> auto& { return o.strong_fold_angle_degrees; },
              "folds bent less than this are drawn as faint gentle-bend marks", between(0, 180))
          .add(
              "spacing_mm", [](O & o) -> auto& { return o.spacing_mm; }, "gap between pieces",
              at_least(0));
  if (nesting) {
    table
        .add(
            "nest_rotations", [](O & o) -> auto& { return o.nest_rotations; },
            "rotations tried per piece (every 360/n degrees)", at_least(1))
        .add(
            "nest_cell_mm", [](O & o) -> auto& { return o.nest_cell_mm; },
            "raster cell of the nesting (finer packs tighter, slower)", greater_than(0))
        .add(
            "nest_repacks", [](O & o) -> auto& { return o.nest_repacks; },
            "fills made again with the last page's pieces first while that saves paper",
            between(0, 10))
        .add(
            "split_long_strips", [](O & o) -> auto& { return o.split_long_strips; },
            "lay out again with long thin strips split in parts of half a page, or where they "
            "bend; kept where that needs fewer pages")
        .add(
            "splits_per_page", [](O & o) -> auto& { return o.splits_per_page; },
            "more pieces (long thin strips split) that one page saved is worth (more: less "
            "paper, more pieces)",
            at_least(1))
        .choice(
            "packing", [](O & o) -> auto& { return o.packing; },
            std::vector<std::pair<std::string, PackingMethod>>{
                {"nest", PackingMethod::Nest},
                {"maxrects", PackingMethod::MaxRects},
                {"shelf", PackingMethod::Shelf}},
            "nest (true outlines), maxrects or shelf (bounding rectangles)");
  } else {
    table.choice(
        "packing", [](O & o) -> auto& { return o.packing; },
        std::vector<std::pair<std::string, PackingMethod>>{{"maxrects", PackingMethod::MaxRects},
                                                           {"shelf", PackingMethod::Shelf}},
        "maxrects or shelf");
  }
  return table;
}

template <class O>
NodeSpec layout_spec(std::string name, std::string summary, const ParamTable<O>& table) {
  return {.name = std::move(name),
          .summary = std::move(summary),
          .input = MessageType::of<ModelStrips>(),
          .outputs = {{"out", MessageType::of<Pattern>()}},
          .params = table.specs(),
          .create = [&table](const Params& params, const NodeContext&) {
            const LayoutOptions options = table.read(params);
            return make_body([options](const Envelope& in, Emitter& out) {
              auto strips = in.get_shared<ModelStrips>();
              // The print scale is the run's, fixed when the model was loaded.
              LayoutOptions run_options = options;
              run_options.scale = in.model->mm_per_unit();
              auto layout =
                  std::make_shared<PatternLayout>(layout_pages(strips->flat, run_options));
              for (const auto& warning : layout->warnings) in.model->note(warning);
              const RunSettings& settings = *in.model->settings;
              const AssemblyEffort effort = assembly_effort(
                  *layout,
                  {.min_width_mm = settings.paper.min_width_mm,
                   .min_area_mm2 = settings.paper.min_area_mm2,
                   .max_narrow_share = PieceLimits{}.max_narrow_share},
                  settings.effort);
              in.model->update([&](ModelRecord& record) {
                record.pages = static_cast<int>(layout->pages.size());
                record.shelf_pages = layout->shelf_page_count;
                record.rectangle_pages = layout->rectangle_page_count;
                record.page_fill = layout->stats.page_fill;
                record.seams = layout->stats.seams;
                record.seams_without_tab = layout->stats.seams_without_tab;
                record.joining_strips = layout->stats.joining_strips;
                record.smallest_text_mm = layout->stats.smallest_text_mm;
                record.overlapping_text = layout->stats.overlapping_text;
                record.effort = effort;
                record.effort_measured = true;
              });
              Pattern pattern;
              pattern.strips = strips;
              pattern.layout = layout;
              out.emit("out", std::move(pattern));
            });
          }};
}

}  // namespace

void register_layout_pages(Registry& registry) {
  static const auto pages = layout_table<LayoutOptions>(true);
  static const auto rectangles = layout_table<RectangleLayoutOptions>(false);
  registry.add(layout_spec("layout.pages",
                           "real scale; pieces nested by their outlines at every 15 degrees "
                           "(never more pages than rectangle packing)",
                           pages));
  registry.add(layout_spec("layout.rectangles",
                           "real scale; pieces packed by their tightest bounding rectangles "
                           "(MaxRects), to compare with layout.pages",
                           rectangles));
}

}  // namespace papercraft
