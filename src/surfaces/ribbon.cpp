// Evaluation of the generic ribbon and the trefoil and unknot ribbons of the paper's section 6.2.
#include "ribbon.h"
#include "builtin.h"

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {

ParameterDomain RibbonSurface::domain() const {
  return {.u0 = 0, .u1 = 2 * std::numbers::pi, .v0 = 0, .v1 = spec_.width, .u_gluing = Gluing::Periodic};
}

SurfaceJet RibbonSurface::evaluate(double u, double v) const {
  const SpaceCurveJet c = spec_.curve(u);
  const Vector3 zero(0, 0, 0);
  return {
      CGAL::ORIGIN + (c.position + v * spec_.direction), c.d1, spec_.direction, c.d2, zero, zero};
}

std::unique_ptr<Surface> make_trefoil_ribbon() {
  RibbonSpec spec;
  spec.name = "trefoil-ribbon";
  spec.description =
      "trefoil (sin s + 2 sin 2s, cos s - 2 cos 2s, -sin 3s) extruded 0.5 along z (two linked "
      "trefoils)";
  spec.curve = [](double s) {
    const double s1 = std::sin(s), c1 = std::cos(s);
    const double s2 = std::sin(2 * s), c2 = std::cos(2 * s);
    const double s3 = std::sin(3 * s), c3 = std::cos(3 * s);
    return SpaceCurveJet{Vector3(s1 + 2 * s2, c1 - 2 * c2, -s3),
                         Vector3(c1 + 4 * c2, -s1 + 4 * s2, -3 * c3),
                         Vector3(-s1 - 8 * s2, -c1 + 8 * c2, 9 * s3)};
  };
  // The three crossings of the z-projection have height gap 1.452 > 0.5.
  spec.width = 0.5;
  spec.topology = ExpectedTopology{0, 2, true, {"trefoil", "trefoil"}, 3};
  return std::make_unique<RibbonSurface>(std::move(spec));
}

std::unique_ptr<Surface> make_unknot_ribbon() {
  RibbonSpec spec;
  spec.name = "unknot-ribbon";
  spec.description =
      "unknot 2 (sin s, sin s cos s, 0.5 cos s) extruded 0.5 along z (two unknots, |lk| 1)";
  spec.curve = [](double s) {
    const double s1 = std::sin(s), c1 = std::cos(s);
    const double s2 = std::sin(2 * s), c2 = std::cos(2 * s);
    return SpaceCurveJet{Vector3(2 * s1, s2, c1), Vector3(2 * c1, 2 * c2, -s1),
                         Vector3(-2 * s1, -4 * s2, -c1)};
  };
  // The z-projection (2 sin s, sin 2s) is a figure eight crossing once, at s = 0 and s = pi,
  // where the heights are +1 and -1: a gap of 2, so a width of a quarter of it keeps the strip
  // embedded with margin. One crossing gives writhe +-1, and the push-off along the projection
  // direction links with linking number = writhe.
  spec.width = 0.5;
  spec.topology = ExpectedTopology{0, 2, true, {"unknot", "unknot"}, 1};
  return std::make_unique<RibbonSurface>(std::move(spec));
}

}  // namespace envcrust::surfaces
