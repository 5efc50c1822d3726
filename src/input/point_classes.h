// Choosing points by their class (a LAS file's classification: 2 ground, 6 building, ...).
#pragma once

#include "envcrust/attributes.h"

#include <string>
#include <vector>

namespace envcrust::input {

/// Keeps the points whose "classification" attribute is one of `classes` (every point when
/// `classes` is empty), with their normals and attributes, and notes how many. Messages start
/// with `name`.
/// @throws InvalidInput "the points have no classification to choose classes 2, 6 from",
///   "no point is of class 7 (the points' classes: 1 (120 points), 2 (3000 points))".
void keep_classes(AttributedPoints& points, const std::vector<int>& classes, const std::string& name,
                  std::vector<std::string>& notes);

}  // namespace envcrust::input
