// Private factories of the built-in surfaces and the pole inset shared by the derived quantities.
#pragma once

#include "envcrust/surfaces.h"

#include <memory>

namespace envcrust::surfaces {

std::unique_ptr<Surface> make_cylinder();
std::unique_ptr<Surface> make_cylinder_nurbs();
std::unique_ptr<Surface> make_paraboloid();
std::unique_ptr<Surface> make_horn();
std::unique_ptr<Surface> make_cusp();
std::unique_ptr<Surface> make_trefoil_ribbon();
std::unique_ptr<Surface> make_unknot_ribbon();
std::unique_ptr<Surface> make_moebius();
std::unique_ptr<Surface> make_hemisphere();
std::unique_ptr<Surface> make_square();
std::unique_ptr<Surface> make_saddle();
std::unique_ptr<Surface> make_sphere();
std::unique_ptr<Surface> make_torus();

/// Fraction of the v range by which a pole is approached when the jet there is degenerate.
inline constexpr double pole_inset_fraction = 1e-6;

/// v moved off a pole edge (into the domain) so that S_u x S_v no longer vanishes.
inline double away_from_pole(const ParameterDomain& domain, double v) {
  const double inset = pole_inset_fraction * (domain.v1 - domain.v0);
  if (domain.v0_is_pole && v < domain.v0 + inset) return domain.v0 + inset;
  if (domain.v1_is_pole && v > domain.v1 - inset) return domain.v1 - inset;
  return v;
}

/// Unit normal S_u x S_v / |.| at (u, v), taken just inside the domain at a pole.
Vector3 unit_normal_at(const Surface& surface, double u, double v);

}  // namespace envcrust::surfaces
