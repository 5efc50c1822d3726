// Graph-like disks: the flat square [-1,1]^2 and the saddle z = x^2 - y^2 over the unit disk.
#include "builtin.h"

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {

namespace {

class Square final : public Surface {
 public:
  [[nodiscard]] std::string name() const override { return "square"; }
  [[nodiscard]] std::string description() const override {
    return "flat square [-1,1]^2 in the plane z = 0 (four corners)";
  }
  [[nodiscard]] ParameterDomain domain() const override {
    return {.u0 = -1, .u1 = 1, .v0 = -1, .v1 = 1};
  }
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override {
    const Vector3 zero(0, 0, 0);
    return {Point3(u, v, 0), Vector3(1, 0, 0), Vector3(0, 1, 0), zero, zero, zero};
  }
  [[nodiscard]] ExpectedTopology expected_topology() const override {
    return ExpectedTopology{1, 1, true, {"unknot"}, 0};
  }
};

/// Polar parametrization (angle u, radius v) so the boundary is the smooth circle r = 1.
class Saddle final : public Surface {
 public:
  [[nodiscard]] std::string name() const override { return "saddle"; }
  [[nodiscard]] std::string description() const override {
    return "saddle z = x^2 - y^2 over the unit disk (polar parametrization)";
  }
  [[nodiscard]] ParameterDomain domain() const override {
    return {.u0 = 0,
            .u1 = 2 * std::numbers::pi,
            .v0 = 0,
            .v1 = 1,
            .u_gluing = Gluing::Periodic,
            .v0_is_pole = true};
  }
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override {
    const double cu = std::cos(u), su = std::sin(u);
    const double c2 = std::cos(2 * u), s2 = std::sin(2 * u);
    const double r = v;
    SurfaceJet jet;
    jet.position = Point3(r * cu, r * su, r * r * c2);
    jet.du = Vector3(-r * su, r * cu, -2 * r * r * s2);
    jet.dv = Vector3(cu, su, 2 * r * c2);
    jet.duu = Vector3(-r * cu, -r * su, -4 * r * r * c2);
    jet.duv = Vector3(-su, cu, -4 * r * s2);
    jet.dvv = Vector3(0, 0, 2 * c2);
    return jet;
  }
  [[nodiscard]] ExpectedTopology expected_topology() const override {
    return ExpectedTopology{1, 1, true, {"unknot"}, 0};
  }
};

}  // namespace

std::unique_ptr<Surface> make_square() { return std::make_unique<Square>(); }
std::unique_ptr<Surface> make_saddle() { return std::make_unique<Saddle>(); }

}  // namespace envcrust::surfaces
