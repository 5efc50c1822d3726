// Before an envelope run with a given rho: can the input's sampling support that rho, and does
// its envelope fit a size budget? `envcrust reconstruct` and `envcrust envelope` refuse a rho
// that fails either, in a fraction of a second instead of after minutes and gigabytes, and name
// one that passes (--force runs it anyway).
#pragma once

#include "envcrust/envelope.h"

#include <string>

namespace envcrust::cli {

/// What a given rho asks of the envelope, predicted from the samples alone.
struct RhoSupport {
  double rho = 0.0;               ///< the rho asked for
  std::size_t input_samples = 0;  ///< samples of M
  double spacing_rel_rho = 0.25;  ///< the envelope's sample spacing, in rho (--spacing)
  /// Smallest rho whose envelope bridges the gaps of 99% of the samples: that quantile of their
  /// distances to their 8th nearest other sample over 2.5 (what the automatic rho never goes
  /// below; envelope::EnvelopeOptions::gap_quantile). Below it the envelope has holes.
  double min_rho_for_gaps = 0.0;
  double predicted_samples = 0.0;  ///< envelope samples predicted at rho
  double budget = 0.0;             ///< most envelope samples allowed (kEnvelopeBudget*)
  double workable_rho = 0.0;       ///< smallest rho (2 significant digits) that passes both
  [[nodiscard]] bool is_below_gaps() const { return rho < min_rho_for_gaps; }
  [[nodiscard]] bool is_over_budget() const { return predicted_samples > budget; }
  [[nodiscard]] bool is_supported() const { return !is_below_gaps() && !is_over_budget(); }
};

/// The envelope may hold this many samples per input sample, and at least kEnvelopeBudgetMin
/// and at most kEnvelopeBudgetMax in all (a Delaunay triangulation of 3 million envelope
/// samples took 3 GB).
inline constexpr double kEnvelopeBudgetPerSample = 50.0;
inline constexpr double kEnvelopeBudgetMin = 1e6;
inline constexpr double kEnvelopeBudgetMax = 5e6;

/// Envelope samples predicted for `samples` at a uniform `rho` and a spacing of
/// `spacing_rel_rho` rho: the two sheets (area from each sample's 8th-neighbour disk, at most
/// the candidates sample_envelope makes per sample) and the rims' half-tubes along the
/// boundary curves, thinned to the Poisson-disk density of that spacing.
double predict_envelope_samples(const envelope::SurfaceSamples& samples, const std::vector<double>& rk, double rho,
                                double spacing_rel_rho);

/// The prediction and the checks for a given uniform rho (> 0). @pre samples has >= 2 points.
RhoSupport rho_support(const envelope::SurfaceSamples& samples, double rho, double spacing_rel_rho);

/// The one-line refusal of an unsupported rho: why, and the rho that would pass ("... use
/// --rho 0.034 or more (or --rho auto), or --force to run it anyway").
std::string rho_refusal(const std::string& input, const RhoSupport& support);

}  // namespace envcrust::cli
