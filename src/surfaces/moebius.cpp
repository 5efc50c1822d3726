// The Moebius strip: a half-twisted band around the unit circle, glued with a flip.
#include "builtin.h"

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {

namespace {

constexpr double half_width = 0.4;

class Moebius final : public Surface {
 public:
  [[nodiscard]] std::string name() const override { return "moebius"; }
  [[nodiscard]] std::string description() const override {
    return "Moebius strip ((1 + v cos(u/2)) cos u, (1 + v cos(u/2)) sin u, v sin(u/2)), "
           "v in [-0.4,0.4]";
  }
  [[nodiscard]] ParameterDomain domain() const override {
    return {.u0 = 0,
            .u1 = 2 * std::numbers::pi,
            .v0 = -half_width,
            .v1 = half_width,
            .u_gluing = Gluing::PeriodicFlipped};
  }
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override {
    const double cu = std::cos(u), su = std::sin(u);
    const double ch = std::cos(u / 2), sh = std::sin(u / 2);
    const double radius = 1 + v * ch;
    const double radius_u = -0.5 * v * sh;
    const double radius_uu = -0.25 * v * ch;
    SurfaceJet jet;
    jet.position = Point3(radius * cu, radius * su, v * sh);
    jet.du = Vector3(radius_u * cu - radius * su, radius_u * su + radius * cu, 0.5 * v * ch);
    jet.dv = Vector3(ch * cu, ch * su, sh);
    jet.duu = Vector3(radius_uu * cu - 2 * radius_u * su - radius * cu,
                      radius_uu * su + 2 * radius_u * cu - radius * su, -0.25 * v * sh);
    jet.duv = Vector3(-0.5 * sh * cu - ch * su, -0.5 * sh * su + ch * cu, 0.5 * ch);
    jet.dvv = Vector3(0, 0, 0);
    return jet;
  }
  [[nodiscard]] ExpectedTopology expected_topology() const override {
    return ExpectedTopology{0, 1, false, {"unknot"}, 0};
  }
};

}  // namespace

std::unique_ptr<Surface> make_moebius() { return std::make_unique<Moebius>(); }

}  // namespace envcrust::surfaces
