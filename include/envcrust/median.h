// The upper median of a set of values: the one statistic several stages take of neighbourhoods.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace envcrust {

/// The upper median of `values` (the element at size / 2 once sorted), reordering them in
/// place; 0 when empty.
inline double upper_median_in_place(std::span<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/// The upper median of `values` (taken by copy); 0 when empty.
inline double upper_median(std::vector<double> values) { return upper_median_in_place(values); }

}  // namespace envcrust
