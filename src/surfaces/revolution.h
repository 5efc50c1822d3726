// A generic surface of revolution of a profile (radius r(s), axial height a(s)) with exact
// derivatives.
#pragma once

#include "envcrust/surfaces.h"

#include <functional>
#include <string>

namespace envcrust::surfaces {

/// Profile values and their first two derivatives in s.
struct ProfileJet {
  double r = 0, dr = 0, ddr = 0;  ///< distance from the axis
  double a = 0, da = 0, dda = 0;  ///< position along the axis
};

/// Everything that defines one surface of revolution.
struct RevolutionSpec {
  std::string name, description;
  std::function<ProfileJet(double)> profile;
  double s0 = 0, s1 = 1;
  bool s0_is_pole = false, s1_is_pole = false;  ///< r(s) = 0 there
  Vector3 axis = Vector3(0, 0, 1);              ///< frame (e1, e2, axis); left-handed turns the normal
  Vector3 e1 = Vector3(1, 0, 0), e2 = Vector3(0, 1, 0);
  ExpectedTopology topology;
};

/// S(u, v) = a(v) axis + r(v) (cos u e1 + sin u e2), u in [0, 2 pi] periodic, v = s.
class RevolutionSurface final : public Surface {
 public:
  explicit RevolutionSurface(RevolutionSpec spec) : spec_(std::move(spec)) {}

  [[nodiscard]] std::string name() const override { return spec_.name; }
  [[nodiscard]] std::string description() const override { return spec_.description; }
  [[nodiscard]] ParameterDomain domain() const override;
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override;
  [[nodiscard]] ExpectedTopology expected_topology() const override { return spec_.topology; }

 private:
  RevolutionSpec spec_;
};

}  // namespace envcrust::surfaces
