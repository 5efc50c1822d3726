// A user's NURBS patch (from a CAD exchange file) as a parametric surface with exact geometry.
#pragma once

#include "envcrust/surfaces.h"
#include "envcrust/types.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::surfaces {

/// A curve of the parameter plane, (u, v) as a rational B-spline (a line: degree 1, knots
/// 0 0 1 1, its two ends; a polyline: degree 1 through its points).
struct TrimCurve {
  int degree = 1;
  std::vector<double> knots;               ///< points + degree + 1, non-decreasing
  std::vector<std::array<double, 2>> points;
  std::vector<double> weights;             ///< > 0, one per point
};

/// A tensor-product rational B-spline patch as exchange files give it.
struct NurbsPatch {
  int degree_u = 0, degree_v = 0;
  std::size_t count_u = 0, count_v = 0;  ///< control points along u and along v
  std::vector<double> knots_u, knots_v;  ///< count + degree + 1 each, non-decreasing
  /// count_u * count_v points and weights, u index fastest: P(i, j) = control_points[i + count_u * j].
  std::vector<Point3> control_points;
  std::vector<double> weights;  ///< > 0; all 1 for a polynomial patch
  /// [u0, u1, v0, v1] within the knots' valid range; nullopt: the whole valid range.
  std::optional<std::array<double, 4>> parameter_range;
  /// Trimming: closed loops of the parameter plane, each a chain of curves end to end; the
  /// kept region is the points inside an odd number of loops. Empty: untrimmed.
  std::vector<std::vector<TrimCurve>> trim_loops;
};

/// The patch as a Surface: exact jet (second derivatives by the quotient rule), the edges
/// that coincide glued (periodic, or reversed as on a Moebius strip), edges that collapse to a
/// point made poles, and the expected topology derived from that (the knot type of each
/// boundary loop from its polyline). A trimmed patch keeps the region its loops bound (each
/// loop's curves evaluated at 512 points), its boundary the loops; its expected Euler
/// characteristic counts the outer loops (inside an even number of others) less the holes.
/// `name` names the surface in reports (a file's stem).
/// @throws InvalidInput with a one-line reason (degree outside 1..8, sizes, a weight not
///   > 0, a non-finite value, decreasing knots, an empty parameter range, collapsed edges in
///   both directions, a Klein bottle, S_u x S_v vanishing inside the patch; a trim loop that
///   does not close, leaves the domain or bounds no area; trimming a patch that closes up).
std::unique_ptr<Surface> make_nurbs_surface(NurbsPatch patch, std::string name);

}  // namespace envcrust::surfaces
