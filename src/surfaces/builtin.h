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

/// Where a boundary curve passes: position, unit tangent, normal and outward conormal.
struct BoundaryFrame {
  Point3 position;
  Vector3 tangent, normal, conormal;
};

/// The boundary vertex at `here`; at a corner (`incoming`: the frame of the piece arriving)
/// it takes that piece's tangent and conormal, so that they stay orthogonal, and keeps its
/// own conormal as conormal_next.
inline BoundaryVertex boundary_vertex(const BoundaryFrame& here, const BoundaryFrame* incoming = nullptr) {
  if (incoming == nullptr) return {here.position, here.tangent, here.normal, here.conormal, false, Vector3(0, 0, 0)};
  return {here.position, incoming->tangent, here.normal, incoming->conormal, true, here.conormal};
}

/// boundary_curves of a trimmed surface: its trim loops mapped onto it (trim_boundary.cpp).
std::vector<BoundaryCurve> trim_boundary_curves(const Surface& surface, double max_spacing);

/// tessellate of a trimmed surface on an nu x nv parameter grid (trim_tessellation.cpp).
TriangleMesh tessellate_trimmed(const Surface& surface, int nu, int nv);

}  // namespace envcrust::surfaces
