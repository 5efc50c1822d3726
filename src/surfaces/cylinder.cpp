// The unit cylinder z in [-1,1], analytically and as the paper's quadratic rational NURBS.
#include "builtin.h"
#include "nurbs_curve.h"

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {

namespace {

ExpectedTopology open_tube_topology() {
  return ExpectedTopology{0, 2, true, {"unknot", "unknot"}, 0};
}

class Cylinder final : public Surface {
 public:
  [[nodiscard]] std::string name() const override { return "cylinder"; }
  [[nodiscard]] std::string description() const override {
    return "open cylinder of radius 1 around the z-axis, z in [-1,1], no caps";
  }
  [[nodiscard]] ParameterDomain domain() const override {
    return {.u0 = 0, .u1 = 2 * std::numbers::pi, .v0 = -1, .v1 = 1, .u_gluing = Gluing::Periodic};
  }
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override {
    const double c = std::cos(u), s = std::sin(u);
    return {Point3(c, s, v),    Vector3(-s, c, 0), Vector3(0, 0, 1),
            Vector3(-c, -s, 0), Vector3(0, 0, 0),  Vector3(0, 0, 0)};
  }
  [[nodiscard]] ExpectedTopology expected_topology() const override { return open_tube_topology(); }
};

RationalBSplineCurve unit_circle_nurbs() {
  const double h = std::numbers::sqrt2 / 2;
  std::vector<Eigen::Vector3d> points{{1, 0, 0},   {1, 1, 0},  {0, 1, 0},  {-1, 1, 0}, {-1, 0, 0},
                                      {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
  std::vector<double> weights{1, h, 1, h, 1, h, 1, h, 1};
  std::vector<double> knots{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  return RationalBSplineCurve(2, std::move(points), std::move(weights), std::move(knots));
}

class CylinderNurbs final : public Surface {
 public:
  CylinderNurbs() : circle_(unit_circle_nurbs()) {}

  [[nodiscard]] std::string name() const override { return "cylinder-nurbs"; }
  [[nodiscard]] std::string description() const override {
    return "the cylinder as the paper's quadratic rational NURBS circle (9 points) extruded over "
           "z in [-1,1]";
  }
  [[nodiscard]] ParameterDomain domain() const override {
    return {.u0 = circle_.first_parameter(),
            .u1 = circle_.last_parameter(),
            .v0 = -1,
            .v1 = 1,
            .u_gluing = Gluing::Periodic};
  }
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override {
    const CurveJet c = circle_.evaluate(u);
    return {Point3(c.position.x(), c.position.y(), v),
            Vector3(c.d1.x(), c.d1.y(), 0),
            Vector3(0, 0, 1),
            Vector3(c.d2.x(), c.d2.y(), 0),
            Vector3(0, 0, 0),
            Vector3(0, 0, 0)};
  }
  [[nodiscard]] ExpectedTopology expected_topology() const override { return open_tube_topology(); }

 private:
  RationalBSplineCurve circle_;
};

}  // namespace

std::unique_ptr<Surface> make_cylinder() { return std::make_unique<Cylinder>(); }
std::unique_ptr<Surface> make_cylinder_nurbs() { return std::make_unique<CylinderNurbs>(); }

}  // namespace envcrust::surfaces
