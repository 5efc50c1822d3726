// Jets, normals and principal curvatures of the built-in surfaces against analytic values.
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {
namespace {

constexpr double pi = std::numbers::pi;

double length(const Vector3& v) { return std::sqrt(v.squared_length()); }

TEST(Jets, match_central_differences_for_every_builtin) {
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    const ParameterDomain d = surface->domain();
    for (double a : {0.13, 0.37, 0.61, 0.89}) {
      for (double b : {0.17, 0.5, 0.83}) {
        const double u = d.u0 + a * (d.u1 - d.u0);
        const double v = d.v0 + b * (d.v1 - d.v0);
        const double h = 1e-5 * std::max(d.u1 - d.u0, d.v1 - d.v0);
        const SurfaceJet j = surface->evaluate(u, v);
        const SurfaceJet up = surface->evaluate(u + h, v), um = surface->evaluate(u - h, v);
        const SurfaceJet vp = surface->evaluate(u, v + h), vm = surface->evaluate(u, v - h);
        const double scale = 1 + length(j.duu) + length(j.dvv) + length(j.duv);
        EXPECT_LT(length(j.du - (up.position - um.position) / (2 * h)), 1e-6 * scale) << name;
        EXPECT_LT(length(j.dv - (vp.position - vm.position) / (2 * h)), 1e-6 * scale) << name;
        EXPECT_LT(length(j.duu - (up.du - um.du) / (2 * h)), 1e-5 * scale) << name;
        EXPECT_LT(length(j.duv - (up.dv - um.dv) / (2 * h)), 1e-5 * scale) << name;
        EXPECT_LT(length(j.dvv - (vp.dv - vm.dv) / (2 * h)), 1e-5 * scale) << name;
      }
    }
  }
}

TEST(Jets, glued_edges_meet) {
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    const ParameterDomain d = surface->domain();
    for (double b : {0.0, 0.3, 0.7, 1.0}) {
      const double v = d.v0 + b * (d.v1 - d.v0);
      if (d.u_gluing == Gluing::Periodic) {
        EXPECT_LT(std::sqrt(CGAL::squared_distance(surface->evaluate(d.u0, v).position,
                                                   surface->evaluate(d.u1, v).position)),
                  1e-12)
            << name;
      }
      if (d.u_gluing == Gluing::PeriodicFlipped) {
        EXPECT_LT(
            std::sqrt(CGAL::squared_distance(surface->evaluate(d.u0, d.v0 + d.v1 - v).position,
                                             surface->evaluate(d.u1, v).position)),
            1e-12)
            << name;
      }
    }
    if (d.v0_is_pole) {
      EXPECT_LT(
          std::sqrt(CGAL::squared_distance(surface->evaluate(d.u0, d.v0).position,
                                           surface->evaluate(0.5 * (d.u0 + d.u1), d.v0).position)),
          1e-12)
          << name;
    }
  }
}

TEST(Curvature, point_at_is_finite_with_unit_normal_everywhere_including_poles) {
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    const ParameterDomain d = surface->domain();
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; j <= 8; ++j) {
        const SurfacePoint p =
            surface->point_at(d.u0 + (d.u1 - d.u0) * i / 8, d.v0 + (d.v1 - d.v0) * j / 8);
        EXPECT_TRUE(std::isfinite(p.k1) && std::isfinite(p.k2)) << name;
        EXPECT_NEAR(length(p.normal), 1.0, 1e-12) << name;
        EXPECT_GE(std::abs(p.k1), std::abs(p.k2)) << name;
      }
    }
  }
}

TEST(Curvature, sphere_is_umbilic_with_unit_curvature) {
  const auto sphere = make_builtin("sphere");
  for (double v : {0.0, 0.4, 1.5, 2.9, pi}) {
    const SurfacePoint p = sphere->point_at(1.0, v);
    EXPECT_NEAR(std::abs(p.k1), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(p.k2), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(p.normal * (p.position - CGAL::ORIGIN)), 1.0, 1e-9);
  }
}

TEST(Curvature, cylinder_has_curvatures_one_and_zero) {
  const SurfacePoint p = make_builtin("cylinder")->point_at(0.7, 0.2);
  EXPECT_NEAR(std::abs(p.k1), 1.0, 1e-14);
  EXPECT_NEAR(p.k2, 0.0, 1e-14);
  EXPECT_NEAR(p.normal.z(), 0.0, 1e-15);
}

TEST(Curvature, torus_outer_and_inner_equators) {
  const auto torus = make_builtin("torus");
  const SurfacePoint outer = torus->point_at(0.3, 0.0);
  EXPECT_NEAR(std::abs(outer.k1), 2.5, 1e-12);
  EXPECT_NEAR(std::abs(outer.k2), 1 / 1.4, 1e-12);
  EXPECT_GT(outer.k1 * outer.k2, 0);  // elliptic
  const SurfacePoint inner = torus->point_at(0.3, pi);
  EXPECT_NEAR(std::abs(inner.k1), 2.5, 1e-12);
  EXPECT_NEAR(std::abs(inner.k2), 1 / 0.6, 1e-12);
  EXPECT_LT(inner.k1 * inner.k2, 0);  // hyperbolic
}

TEST(Curvature, paraboloid_apex_has_curvature_two) {
  const SurfacePoint apex = make_builtin("paraboloid")->point_at(1.0, 0.0);
  EXPECT_NEAR(std::abs(apex.k1), 2.0, 1e-9);
  EXPECT_NEAR(std::abs(apex.k2), 2.0, 1e-9);
  EXPECT_NEAR(std::abs(apex.normal.x()), 1.0, 1e-9);
  EXPECT_NEAR(apex.position.x(), 0.0, 0.0);
}

TEST(Curvature, saddle_origin_has_curvatures_plus_and_minus_two) {
  const SurfacePoint origin = make_builtin("saddle")->point_at(0.4, 0.0);
  EXPECT_NEAR(std::abs(origin.k1), 2.0, 1e-9);
  EXPECT_NEAR(std::abs(origin.k2), 2.0, 1e-9);
  EXPECT_LT(origin.k1 * origin.k2, 0);
  EXPECT_NEAR(std::abs(origin.normal.z()), 1.0, 1e-9);
}

TEST(Curvature, hemisphere_and_square) {
  const SurfacePoint top = make_builtin("hemisphere")->point_at(2.0, 0.0);
  EXPECT_NEAR(top.position.z(), 1.0, 1e-15);
  EXPECT_NEAR(std::abs(top.k1), 1.0, 1e-9);
  const SurfacePoint flat = make_builtin("square")->point_at(0.3, -0.2);
  EXPECT_EQ(flat.k1, 0.0);
  EXPECT_EQ(flat.k2, 0.0);
  EXPECT_NEAR(std::abs(flat.normal.z()), 1.0, 0.0);
}

TEST(Curvature, cusp_apex_curvature_is_large_but_finite) {
  const auto cusp = make_builtin("cusp");
  const SurfacePoint apex = cusp->point_at(0.0, 0.0);
  EXPECT_TRUE(std::isfinite(apex.k1));
  EXPECT_GT(std::abs(apex.k1), 100.0);
  // Near the apex the parallel curvature is 1.5 r^(-1/2) and the meridian one 0.75 r^(-1/2).
  const double r = 1e-4, slope = 1.5 * std::sqrt(r);
  const double speed = std::sqrt(1 + slope * slope);
  const SurfacePoint near = cusp->point_at(0.0, r);
  EXPECT_NEAR(std::abs(near.k1), slope / (r * speed), 1e-8);
  EXPECT_NEAR(std::abs(near.k2), 0.75 / std::sqrt(r) / (speed * speed * speed), 1e-8);
}

TEST(Curvature, horn_matches_the_revolution_formulas) {
  // Profile r = x^(-3/2) along the x-axis: meridian and parallel curvatures.
  const double x = 1.0;
  const double r = std::pow(x, -1.5), dr = -1.5 * r / x, ddr = 3.75 * r / (x * x);
  const double speed = std::sqrt(1 + dr * dr);
  const double meridian = std::abs(ddr) / (speed * speed * speed);
  const double parallel = 1 / (r * speed);
  const SurfacePoint p = make_builtin("horn")->point_at(0.5, x);
  EXPECT_NEAR(std::abs(p.k1), std::max(meridian, parallel), 1e-12);
  EXPECT_NEAR(std::abs(p.k2), std::min(meridian, parallel), 1e-12);
}

TEST(Curvature, ribbons_have_one_zero_curvature) {
  for (const char* name : {"trefoil-ribbon", "unknot-ribbon"}) {
    const SurfacePoint p = make_builtin(name)->point_at(1.1, 0.2);
    EXPECT_NEAR(p.k2, 0.0, 1e-12) << name;
    EXPECT_NEAR(p.normal.z(), 0.0, 1e-15) << name;
  }
}

}  // namespace
}  // namespace envcrust::surfaces
