// The reports the module returns, as the CLI's JSON documents turned into Python objects.
#pragma once

#include "envcrust/analysis.h"
#include "envcrust/input.h"
#include "envcrust/pipeline.h"

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

namespace envcrust::python {

/// The analyzer's report under the keys of the CLI's ("analysis" in `envcrust reconstruct
/// --json`, the document of `envcrust analyze --json`): vertices, faces, edges,
/// euler_characteristic, is_orientable, boundary_loops, components, is_manifold, loops (each
/// with its knot), linking, distance (when measured), self_intersections, component_list, warnings.
nlohmann::json analysis_json(const analysis::AnalysisReport& report);

/// What a run's report holds beyond the library's results: the analysis of the result, its
/// boundary check and the checks that failed (all unset without analysis).
struct RunChecks {
  std::optional<analysis::AnalysisReport> analysis;
  std::optional<analysis::BoundaryCheck> boundary_check;
  std::vector<Polyline> curves;     ///< the input's boundary curves the check compared with
  std::vector<std::string> failed;  ///< one line per failed check, as the CLI's "checks"
  std::size_t uncovered_patches = 0;  ///< patches of input samples the result leaves out (pipeline::uncovered_patches)
  std::vector<std::string> warnings;
};

/// The report of a reconstruction, with the keys of `envcrust reconstruct --json` (input
/// "points", source "points"; no output file, no hints).
nlohmann::json reconstruct_json(const input::PreparedInput& prepared, const pipeline::ReconstructResult& result,
                                const pipeline::ReconstructOptions& options, const RunChecks& checks, int threads);

/// A JSON document as Python objects: dicts, lists, str, int, float, bool and None.
pybind11::object to_python(const nlohmann::json& document);

}  // namespace envcrust::python
