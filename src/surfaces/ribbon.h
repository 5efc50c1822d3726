// A ribbon: a closed space curve extruded a fixed width along a fixed direction.
#pragma once

#include "envcrust/surfaces.h"

#include <functional>
#include <string>

namespace envcrust::surfaces {

/// A space curve's position and first two derivatives at one parameter.
struct SpaceCurveJet {
  Vector3 position, d1, d2;  ///< position as a vector from the origin
};

/// Everything that defines one ribbon.
struct RibbonSpec {
  std::string name, description;
  std::function<SpaceCurveJet(double)> curve;  ///< 2 pi periodic in s
  Vector3 direction = Vector3(0, 0, 1);        ///< never parallel to the curve's tangent
  double width = 0.5;
  ExpectedTopology topology;
};

/// S(s, v) = gamma(s) + v d, s in [0, 2 pi] periodic, v in [0, width]: a strip of the cylinder
/// over gamma's projection along d, embedded iff the strands clear each other by more than the
/// width at every crossing of that projection.
class RibbonSurface final : public Surface {
 public:
  explicit RibbonSurface(RibbonSpec spec) : spec_(std::move(spec)) {}

  [[nodiscard]] std::string name() const override { return spec_.name; }
  [[nodiscard]] std::string description() const override { return spec_.description; }
  [[nodiscard]] ParameterDomain domain() const override;
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override;
  [[nodiscard]] ExpectedTopology expected_topology() const override { return spec_.topology; }

 private:
  RibbonSpec spec_;
};

}  // namespace envcrust::surfaces
