// Dense candidate points on the envelope (sheets, rims, lunes), before thinning.
#pragma once

#include "envcrust/envelope.h"

#include <cstdint>
#include <vector>

namespace envcrust::envelope {

/// Sheet candidates g +- rho_i n (rho one value per sample, h_i = spacing_rel_rho rho_i):
/// each input sample spreads `m` generators uniformly over the tangent disk of radius r_k
/// (`neighbour_distance`, from neighbour_distances in input_tree.h), with m chosen so that the sheets get about
/// `per_h2` candidates per h^2 (input denser than that keeps each sample as a generator with
/// the matching probability).
std::vector<EnvelopeSample> sheet_candidates(const SurfaceSamples& surface, const std::vector<double>& rho,
                                             double spacing_rel_rho, double per_h2, std::uint64_t seed,
                                             const std::vector<double>& neighbour_distance);

/// Rim half-circles b + rho (cos t n + sin t c), t in [0, pi], along every boundary curve
/// resampled at arc length <= step_rel_h * h, and lunes at convex corners; rim_rho holds rho per
/// curve vertex, h = spacing_rel_rho rho.
std::vector<EnvelopeSample> rim_candidates(const std::vector<BoundaryCurve>& boundary,
                                           const std::vector<std::vector<double>>& rim_rho,
                                           double spacing_rel_rho, double step_rel_h);

/// The number of candidates rim_candidates makes for these arguments, computed without making
/// them (a rho far too small for the curves would exhaust memory).
double rim_candidate_count(const std::vector<BoundaryCurve>& boundary,
                           const std::vector<std::vector<double>>& rim_rho, double spacing_rel_rho,
                           double step_rel_h);

}  // namespace envcrust::envelope
