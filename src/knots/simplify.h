// Simplification of closed polylines by Delta-moves that are exact isotopies.
#pragma once

#include "envcrust/types.h"

#include <vector>

namespace envcrust::knots::detail {

/// Repeatedly deletes a vertex v_i when the triangle v_{i-1} v_i v_{i+1} meets no other
/// segment of any loop (exact predicates), until no vertex can be deleted. The loops are
/// simplified together, so the link type (not only each knot type) is preserved. No loop is
/// reduced below 3 vertices. Loops must be free of consecutive repeated points.
std::vector<Polyline> simplify_loops(const std::vector<Polyline>& loops);

}  // namespace envcrust::knots::detail
