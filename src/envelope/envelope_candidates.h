// Dense candidate points on the envelope (sheets, rims, lunes), before thinning.
#pragma once

#include "envcrust/envelope.h"

#include <cstdint>
#include <vector>

namespace envcrust::envelope {

/// Sheet candidates g +- rho n: each input sample spreads `m` generators uniformly over the
/// tangent disk of radius r_k (distance to its k-th neighbour), with m chosen so that the
/// sheets get about `per_h2` candidates per h^2. Returns also the largest r_k seen.
std::vector<EnvelopeSample> sheet_candidates(const SurfaceSamples& surface, double rho, double h,
                                             double per_h2, std::uint64_t seed,
                                             double& largest_gap);

/// Rim half-circles b + rho (cos t n + sin t c), t in [0, pi], along every boundary curve
/// resampled at arc length <= step, and lunes at convex corners.
std::vector<EnvelopeSample> rim_candidates(const std::vector<BoundaryCurve>& boundary, double rho,
                                           double step);

}  // namespace envcrust::envelope
