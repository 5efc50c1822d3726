// Evaluation of the generic surface of revolution and the built-ins made from it.
#include "revolution.h"
#include "builtin.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace envcrust::surfaces {

ParameterDomain RevolutionSurface::domain() const {
  return {.u0 = 0,
          .u1 = 2 * std::numbers::pi,
          .v0 = spec_.s0,
          .v1 = spec_.s1,
          .u_gluing = Gluing::Periodic,
          .v0_is_pole = spec_.s0_is_pole,
          .v1_is_pole = spec_.s1_is_pole};
}

SurfaceJet RevolutionSurface::evaluate(double u, double v) const {
  const ProfileJet p = spec_.profile(v);
  const double c = std::cos(u), s = std::sin(u);
  const Vector3 radial = c * spec_.e1 + s * spec_.e2;
  const Vector3 tangential = -s * spec_.e1 + c * spec_.e2;
  SurfaceJet jet;
  jet.position = CGAL::ORIGIN + (p.a * spec_.axis + p.r * radial);
  jet.du = p.r * tangential;
  jet.dv = p.da * spec_.axis + p.dr * radial;
  jet.duu = -p.r * radial;
  jet.duv = p.dr * tangential;
  jet.dvv = p.dda * spec_.axis + p.ddr * radial;
  return jet;
}

namespace {

/// Right-handed frame (e1, e2, axis) with the axis along x, y or z.
void set_axis(RevolutionSpec& spec, int axis) {
  const Vector3 unit[3] = {Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1)};
  spec.axis = unit[axis];
  spec.e1 = unit[(axis + 1) % 3];
  spec.e2 = unit[(axis + 2) % 3];
}

ExpectedTopology disk_topology() { return ExpectedTopology{1, 1, true, {"unknot"}, 0}; }

RevolutionSpec sphere_spec(double theta1) {
  RevolutionSpec spec;
  spec.profile = [](double theta) {
    const double s = std::sin(theta), c = std::cos(theta);
    return ProfileJet{s, c, -s, c, -s, -c};
  };
  spec.s0 = 0;
  spec.s1 = theta1;
  spec.s0_is_pole = true;
  // u turns clockwise about z (e1 = y, e2 = x) so that S_u x S_v, the normal and the
  // tessellation's winding, point outward (counter-clockwise they point to the centre).
  spec.e1 = Vector3(0, 1, 0);
  spec.e2 = Vector3(1, 0, 0);
  return spec;
}

}  // namespace

std::unique_ptr<Surface> make_paraboloid() {
  RevolutionSpec spec;
  spec.name = "paraboloid";
  spec.description =
      "paraboloid x = y^2, y in [0,2], revolved about the x-axis (apex at the origin)";
  spec.profile = [](double s) { return ProfileJet{s, 1, 0, s * s, 2 * s, 2}; };
  spec.s0 = 0;
  spec.s1 = 2;
  spec.s0_is_pole = true;
  set_axis(spec, 0);
  spec.topology = disk_topology();
  return std::make_unique<RevolutionSurface>(std::move(spec));
}

std::unique_ptr<Surface> make_horn() {
  RevolutionSpec spec;
  spec.name = "horn";
  spec.description = "horn y = x^(-3/2), x in [0.5,2], revolved about the x-axis (a tube)";
  spec.profile = [](double s) {
    const double r = std::pow(s, -1.5);
    return ProfileJet{r, -1.5 * r / s, 3.75 * r / (s * s), s, 1, 0};
  };
  spec.s0 = 0.5;
  spec.s1 = 2;
  set_axis(spec, 0);
  spec.topology = ExpectedTopology{0, 2, true, {"unknot", "unknot"}, 0};
  return std::make_unique<RevolutionSurface>(std::move(spec));
}

std::unique_ptr<Surface> make_cusp() {
  RevolutionSpec spec;
  spec.name = "cusp";
  spec.description =
      "non-C2 cap y = |x|^(3/2), |x| <= 1, revolved about the y-axis (curvature ~ r^(-1/2) at the "
      "apex)";
  spec.profile = [](double s) {
    // a'' = 0.75 s^(-1/2) is infinite at the apex; a tiny floor keeps the jet finite there.
    const double root = std::sqrt(std::max(s, 0.0));
    return ProfileJet{s, 1, 0, s * root, 1.5 * root, 0.75 / std::max(root, 1e-150)};
  };
  spec.s0 = 0;
  spec.s1 = 1;
  spec.s0_is_pole = true;
  set_axis(spec, 1);
  spec.topology = disk_topology();
  return std::make_unique<RevolutionSurface>(std::move(spec));
}

std::unique_ptr<Surface> make_hemisphere() {
  RevolutionSpec spec = sphere_spec(std::numbers::pi / 2);
  spec.name = "hemisphere";
  spec.description = "upper unit hemisphere z >= 0 (pole at the top, boundary circle at z = 0)";
  spec.topology = disk_topology();
  return std::make_unique<RevolutionSurface>(std::move(spec));
}

std::unique_ptr<Surface> make_sphere() {
  RevolutionSpec spec = sphere_spec(std::numbers::pi);
  spec.name = "sphere";
  spec.description = "unit sphere (closed, poles on the z-axis)";
  spec.s1_is_pole = true;
  spec.topology = ExpectedTopology{2, 0, true, {}, 0};
  return std::make_unique<RevolutionSurface>(std::move(spec));
}

}  // namespace envcrust::surfaces
