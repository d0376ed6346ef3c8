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
/// The same for the given connected-or-not subset of the strip's triangles.
std::vector<std::vector<int>> split_to_fit(StripData& data, const std::vector<int>& triangles,
                                           double width, double height,
                                           std::set<std::string>& used_labels);

/// Splits the strip where it bends (an L or a U of a strip round the corners of a model):
/// each cut, at a ruling, is kept where the tightest rectangles round the two parts cover
/// much less paper than the one round the whole; new seams recorded as split_to_fit does.
std::vector<std::vector<int>> split_at_bends(StripData& data, std::set<std::string>& used_labels);

}  // namespace papercraft::layout_internal
