// A point set as read, made usable by the stages: unit normals, repeated points merged,
// refused when too few or on a line.
#pragma once

#include "envcrust/attributes.h"

#include <string>
#include <vector>

namespace envcrust::input {

/// The points as the stages need them: normals scaled to unit length (files store them at any
/// length; the envelope offsets by rho times the normal) and a zero one refused, and repeated
/// points merged (scans repeat points where views overlap; a copy would read as a zero
/// spacing), each keeping its first occurrence's normal and attributes. Normals that are text
/// columns of whole numbers in 0..255 become colours; normals all (0, 0, 0) become none. What
/// was done goes to `notes`; messages start with `name` (input_names.h).
/// @throws InvalidInput a zero normal; DegenerateInput fewer than 5 points left, or all on a line.
AttributedPoints usable_points(AttributedPoints input, bool are_normals_text_columns, const std::string& name,
                               std::vector<std::string>& notes);

}  // namespace envcrust::input
