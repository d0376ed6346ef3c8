#pragma once
// Printing on the back of the sheet: the finished layout mirrored page by page.

#include "core/pattern.h"

namespace papercraft {

/// Mirrors every page of `layout` across its vertical centre line (x -> page width - x), for
/// printing on the back of the sheet: cut from the printed side, the pieces come out the
/// right way round with the print on the inside of the model. Pieces, joining strips, their
/// tabs (and tab textures), cut lines, marks, leaders and folds are mirrored; fold kinds are
/// swapped (a mountain seen from the outside is a valley seen from the inside); labels and
/// numbers keep their mirrored place and read left to right, upright; the scale bar and the
/// footer stay where they are, the footer saying "print on the back" (its right
/// end kept). Sets layout.print_side to Back (the tab bases are then valley
/// folds). Mirroring keeps every distance, so nothing comes to overlap.
/// \pre layout.print_side == Front (a layout is mirrored once).
/// \throws InvalidInputException if the layout is already mirrored.
void mirror_for_back_printing(PatternLayout& layout);

}  // namespace papercraft
