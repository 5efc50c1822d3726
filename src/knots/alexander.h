// Alexander polynomial of a one-loop knot diagram.
#pragma once

#include "polynomial.h"
#include "projection.h"

namespace envcrust::knots::detail {

/// The Alexander polynomial of a diagram with exactly one loop, normalised by normalize_unit
/// (lowest-degree term at t^0, positive constant term). A diagram without crossings gives 1.
Polynomial alexander_polynomial(const Diagram& diagram);

}  // namespace envcrust::knots::detail
