// The closed torus around the z-axis (major radius 1, minor radius 0.4).
#include "builtin.h"

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {

namespace {

constexpr double major_radius = 1.0;
constexpr double minor_radius = 0.4;

class Torus final : public Surface {
 public:
  [[nodiscard]] std::string name() const override { return "torus"; }
  [[nodiscard]] std::string description() const override {
    return "torus around the z-axis, major radius 1, minor radius 0.4 (closed)";
  }
  [[nodiscard]] ParameterDomain domain() const override {
    const double two_pi = 2 * std::numbers::pi;
    return {.u0 = 0,
            .u1 = two_pi,
            .v0 = 0,
            .v1 = two_pi,
            .u_gluing = Gluing::Periodic,
            .v_gluing = Gluing::Periodic};
  }
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override {
    const double cu = std::cos(u), su = std::sin(u);
    const double cv = std::cos(v), sv = std::sin(v);
    const double ring = major_radius + minor_radius * cv;
    const double r = minor_radius;
    SurfaceJet jet;
    jet.position = Point3(ring * cu, ring * su, r * sv);
    jet.du = Vector3(-ring * su, ring * cu, 0);
    jet.dv = Vector3(-r * sv * cu, -r * sv * su, r * cv);
    jet.duu = Vector3(-ring * cu, -ring * su, 0);
    jet.duv = Vector3(r * sv * su, -r * sv * cu, 0);
    jet.dvv = Vector3(-r * cv * cu, -r * cv * su, -r * sv);
    return jet;
  }
  [[nodiscard]] ExpectedTopology expected_topology() const override {
    return ExpectedTopology{0, 0, true, {}, 0};
  }
};

}  // namespace

std::unique_ptr<Surface> make_torus() { return std::make_unique<Torus>(); }

}  // namespace envcrust::surfaces
