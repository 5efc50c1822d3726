// The JSON and text that `envcrust reconstruct` gives of a run's stages (reconstruct_output.cpp).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>

#include "envcrust/envelope.h"
#include "envcrust/pipeline.h"

namespace envcrust::cli {

/// rho (given or automatic, and what set it), the spacing and counts of the envelope samples.
nlohmann::json envelope_json(const envelope::EnvelopeSamples& e);

/// One run's defects as the adaptive retry and the Power Crust fallback compare them.
nlohmann::json defects_json(const pipeline::RunDefects& d, const std::optional<long>& max_genus);
std::string describe(const pipeline::RunDefects& d, const std::optional<long>& max_genus);
std::string describe(const pipeline::AdaptiveRetry& retry);
std::string describe(const pipeline::PowerCrustFallback& fallback, const std::optional<long>& max_genus);

/// The method, the envelope, the seconds per stage, the retry and fallback, the sheet's and the
/// remeshing's statistics, the Power Crust of the envelope's topology (the keys the report
/// gives of the run itself, before the analysis of its result).
nlohmann::json run_stages_json(const pipeline::ReconstructResult& result, const pipeline::ReconstructOptions& options);

/// The same as text lines: rho and the envelope, the retry, the fallback, the time per stage,
/// the remeshing.
void print_run_stages(std::ostream& out, const pipeline::ReconstructResult& result,
                      const pipeline::ReconstructOptions& options);

}  // namespace envcrust::cli
