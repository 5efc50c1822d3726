// The keyword options of envcrust.reconstruct() and the library options they set, as
// `envcrust reconstruct` sets them from its flags.
#pragma once

#include "envcrust/input.h"
#include "envcrust/pipeline.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>

namespace envcrust::python {

/// What reconstruct() was asked, by keyword. The defaults are the CLI's.
struct ReconstructSettings {
  pipeline::ReconstructOptions options;  ///< before options_for_input (the envelope's, method, extraction)
  input::InputOptions input;             ///< outliers, boundary detection, creases; name "points"
  std::string extract;                   ///< sheet, samples or powershape (--extract); empty: by input
  std::string orientable = "auto";       ///< auto, yes or no (--orientable)
  std::optional<double> cut_handles;     ///< --cut-handles; unset: by input
  bool use_remesh = false;               ///< --remesh
  bool use_adaptive_retry = true;        ///< false: --no-adaptive-retry
  bool use_power_crust_fallback = true;  ///< false: --no-power-crust-fallback
  bool force = false;                    ///< --force: run a given rho the sampling cannot support
  bool use_analysis = true;              ///< false: --no-analysis
  int threads = 0;                       ///< --threads; 0: every core
  pybind11::object progress = pybind11::none();  ///< callable(stage: str, fraction: float) or None
};

/// The keywords reconstruct() takes besides points, normals, colors and classification, one line each (its docstring).
extern const char* const kReconstructKeywordsDoc;

/// Settings from reconstruct()'s keyword arguments.
/// @throws TypeError "reconstruct() got an unexpected keyword argument 'foo'", or a value of
///   the wrong type; ValueError "rho must be 'auto', None or a positive number (got -1)" and
///   the like for values out of range.
ReconstructSettings parse_reconstruct_keywords(const pybind11::kwargs& keywords);

/// The options a run on prepared samples of `kind` takes (pipeline::options_for_input), then
/// what was asked: orientable, cut_handles, extract, adaptive_retry, power_crust_fallback.
/// @throws ValueError "orientable and cut_handles apply to the medial sheet (...)".
pipeline::ReconstructOptions options_for_run(const ReconstructSettings& settings, const pipeline::InputKind& kind);

}  // namespace envcrust::python
