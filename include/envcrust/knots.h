// Knot invariants of closed polylines: knot type via the Alexander polynomial, linking numbers.
#pragma once

#include "envcrust/types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace envcrust::knots {

/// Knot types told apart (by the Alexander polynomial; see docs/method.md §9.4). Unknown:
/// every projection tried had more crossings than KnotOptions::max_crossings.
enum class KnotType { Unknot, Trefoil, FigureEight, Other, Unknown };

/// "unknot", "trefoil", "figure-eight", "other", "unknown".
std::string to_string(KnotType type);

/// Options of identify_knot and linking_number.
struct KnotOptions {
  std::uint64_t seed = 1;  ///< seed of the random projection directions
  int projections = 3;     ///< independent projections voted over (>= 1)
  /// Diagrams with more crossings are not read: the Alexander determinant grows about as c^3
  /// (measured 2026-12-03 on random polygons, one projection: 250 crossings 0.10 s, 699
  /// 2.3 s, 1,128 12 s, 2,549 108 s). A curve whose simplest diagram found has more is
  /// reported as KnotType::Unknown.
  int max_crossings = 300;
};

/// Result of identify_knot.
struct KnotReport {
  KnotType type = KnotType::Unknot;
  std::string alexander;          ///< normalised Alexander polynomial, e.g. "t^2 - t + 1"; empty when Unknown
  std::int64_t determinant = 1;   ///< |Delta(-1)|: 1 unknot, 3 trefoil, 5 figure-eight; 0 when Unknown
  int crossings = 0;              ///< crossings of the projection used (after simplification)
  std::size_t simplified_vertices = 0;  ///< vertices left after the Delta-move simplification
  bool projections_agree = true;  ///< all projections gave the same polynomial
};

/// Knot type of a closed polyline (first point not repeated). The polyline is first
/// simplified by Delta-moves that are exact isotopies (a vertex is removed only when the
/// triangle it spans meets no other segment, tested with exact predicates), then projected
/// in random generic directions; the Alexander polynomial is computed exactly (integer
/// polynomial determinant) and voted over the projections.
/// @throws InvalidInput if the polyline has < 3 points or non-finite coordinates.
KnotReport identify_knot(const Polyline& closed, const KnotOptions& options = {});

/// Linking number of two disjoint closed polylines, oriented by their vertex order.
/// @throws InvalidInput on < 3 points; NumericalFailure if no generic projection is found.
int linking_number(const Polyline& a, const Polyline& b, const KnotOptions& options = {});

}  // namespace envcrust::knots
