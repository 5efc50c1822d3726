// Differential geometry derived from a surface's jet: unit normal and principal curvatures.
#include "builtin.h"
#include "vector_ops.h"

#include <cmath>

namespace envcrust::surfaces {

Vector3 unit_normal_at(const Surface& surface, double u, double v) {
  const SurfaceJet jet = surface.evaluate(u, away_from_pole(surface.domain(), v));
  return normalized(cross(jet.du, jet.dv));
}

SurfacePoint Surface::point_at(double u, double v) const {
  // The position is the true one (the pole itself); normal and curvature are limits taken
  // from just inside, where S_u x S_v no longer vanishes.
  const ParameterDomain dom = domain();
  const double v_inside = away_from_pole(dom, v);
  const SurfaceJet jet = evaluate(u, v_inside);

  SurfacePoint result;
  result.position = v_inside == v ? jet.position : evaluate(u, v).position;
  result.normal = normalized(cross(jet.du, jet.dv));

  // The shape operator in the orthonormal tangent frame (e1 = S_u/|S_u|, e2 = n x e1) is a
  // symmetric matrix W = J^-T II J^-1, J = [[alpha, beta], [0, gamma]] expressing S_u, S_v in
  // that frame. Its eigenvalues via (a - c)/2 stay accurate at umbilics, where the usual
  // H +- sqrt(H^2 - K) loses half the digits.
  const double alpha = norm(jet.du);
  if (!(alpha > 0)) return result;  // degenerate jet: report zero curvature, never NaN
  const Vector3 e1 = jet.du / alpha;
  const Vector3 e2 = cross(result.normal, e1);
  const double beta = dot(jet.dv, e1);
  const double gamma = dot(jet.dv, e2);
  if (!(std::abs(gamma) > 0)) return result;
  const double l = dot(jet.duu, result.normal);
  const double m = dot(jet.duv, result.normal);
  const double n = dot(jet.dvv, result.normal);
  // J^-1 = [[1/alpha, -beta/(alpha gamma)], [0, 1/gamma]] =: [[p, q], [0, r]].
  const double p = 1 / alpha, q = -beta / (alpha * gamma), r = 1 / gamma;
  const double w11 = p * p * l;
  const double w12 = p * (q * l + r * m);
  const double w22 = q * q * l + 2 * q * r * m + r * r * n;
  const double half_sum = 0.5 * (w11 + w22);
  const double radius = std::hypot(0.5 * (w11 - w22), w12);
  const double a = half_sum + radius;
  const double b = half_sum - radius;
  result.k1 = std::abs(a) >= std::abs(b) ? a : b;
  result.k2 = std::abs(a) >= std::abs(b) ? b : a;
  return result;
}


}  // namespace envcrust::surfaces
