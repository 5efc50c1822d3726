// The run's JSON report as rows of a table: each scalar under its path ("analysis.topology.
// euler_characteristic"), so that the HTML report shows every figure without a JSON viewer.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace envcrust::cli::html {

/// One row: the value's path in the document and the value as text.
using FigureRow = std::pair<std::string, std::string>;

/// The rows of `report`, depth first in the document's order. Numbers print with 6
/// significant digits; arrays of numbers of up to 8 values on one row ("[1, 2, 3]"), longer
/// ones as "1000 values: 0.1, 0.2, 0.3, ..."; other arrays one row per element ("loops[0].length"),
/// the first `max_elements` of each. At most `max_rows` rows; when rows were left out, the last
/// row says how many.
std::vector<FigureRow> figure_rows(const nlohmann::json& report, std::size_t max_rows = 400,
                                   std::size_t max_elements = 12);

}  // namespace envcrust::cli::html
