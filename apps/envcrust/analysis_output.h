// Presentation of analyzer reports: JSON documents and the human-readable summary.
#pragma once

#include "envcrust/analysis.h"

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>

namespace envcrust::cli {

nlohmann::json knot_json(const knots::KnotReport& knot);
/// "trefoil (Alexander t^2 - t + 1)", or for an unread curve "unknown (N crossings ...)".
std::string knot_text(const knots::KnotReport& knot);
nlohmann::json analysis_json(const analysis::AnalysisReport& report);

/// Print the summary of a mesh analysis, `name` being the analyzed input.
void print_analysis(std::ostream& out, const std::string& name,
                    const analysis::AnalysisReport& report);

}  // namespace envcrust::cli
