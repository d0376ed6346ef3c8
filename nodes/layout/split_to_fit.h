#pragma once
// Splitting a strip that fits no page into pieces that do, cut at inner edges.

#include <set>
#include <string>
#include <vector>

#include "nodes/layout/pieces.h"

namespace papercraft::layout_internal {

/// Splits the strip into connected triangle sets each fitting width x height in their
/// tightest orientation, of similar length, and records the new seams in data.split_label
/// as <strip id>-<k>, made unique against (and added to) `used_labels`.
std::vector<std::vector<int>> split_to_fit(StripData& data, double width, double height,
                                           std::set<std::string>& used_labels);

}  // namespace papercraft::layout_internal
