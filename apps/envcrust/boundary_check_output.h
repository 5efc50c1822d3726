// The reconstruction's boundary loops checked against the input's boundary curves: the
// warnings that name what does not match, and the JSON record.
#pragma once

#include "envcrust/analysis.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace envcrust::cli {

/// One warning per input curve no loop follows and per loop that follows no curve;
/// `tolerance_text` says what the tolerance is ("2 rho = 0.0034").
std::vector<std::string> boundary_check_warnings(const analysis::BoundaryCheck& check,
                                                 const std::vector<Polyline>& curves,
                                                 const topology::MeshTopology& topology,
                                                 const std::string& tolerance_text);

nlohmann::json boundary_check_json(const analysis::BoundaryCheck& check, const std::vector<Polyline>& curves,
                                   const topology::MeshTopology& topology);

/// The warning for a result that leaves `patches` (> 0) patches of the input's samples out
/// (pipeline::uncovered_patches), worded once for the CLI's report and Python's.
std::string uncovered_patches_warning(std::size_t patches);

}  // namespace envcrust::cli
