// Boundary detection where the sampling density jumps: a step across the surface is no
// boundary (BoundaryOptions::drop_density_steps), and a rim sampled sparsely is linked and
// measured in its own spacing (BoundaryOptions::link_in_local_spacing).
#include "envcrust/boundary.h"
#include "envcrust/nearest_index.h"

#include <CGAL/squared_distance_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

namespace envcrust {
namespace {

constexpr double kHoleRadius = 0.2;

// The unit square with a round hole of radius 0.2 at its centre, sampled at random (seed 5):
// `dense` points spread over all of it, and the half x < 0.5 gets `factor` times as many
// (the half x > 0.5 is sampled sqrt(factor) times more sparsely in spacing).
std::vector<Point3> square_with_density_step(std::size_t dense, double factor) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point3> points;
  const auto sparse_every = static_cast<std::size_t>(std::lround(factor));
  std::size_t right = 0;
  while (points.size() < dense) {
    const double x = u(rng), y = u(rng);
    if (std::hypot(x - 0.5, y - 0.5) < kHoleRadius) continue;
    if (x > 0.5 && right++ % sparse_every != 0) continue;
    points.emplace_back(x, y, 0.0);
  }
  return points;
}

// Distance of p from the true boundary: the square's outline or the hole's circle.
double to_true_boundary(const Point3& p) {
  const double outline = std::min({p.x(), 1 - p.x(), p.y(), 1 - p.y()});
  const double hole = std::abs(std::hypot(p.x() - 0.5, p.y() - 0.5) - kHoleRadius);
  // Outside the square the outline distance is negative: take its size.
  return std::min(std::abs(outline), hole);
}

// A tenfold jump in density (about 3.2 times the spacing) across the middle: the dense
// half's samples at the step have all their nearest neighbours on their own side and pass
// the angle-gap test, but the sheet goes on past them. They are no boundary; linked in the
// local spacing, the two true loops come out whole, running through both halves.
TEST(DensityStep, StepAcrossTheSurfaceIsNoBoundaryAndTheRimsStayWhole) {
  const std::vector<Point3> points = square_with_density_step(20000, 10.0);
  const std::vector<Vector3> normals(points.size(), Vector3(0, 0, 1));
  boundary::BoundaryOptions local;
  local.drop_density_steps = true;
  local.link_in_local_spacing = true;
  const auto result = boundary::detect_boundary(points, normals, local);
  ASSERT_EQ(result.curves.size(), 2u);
  // The sampling's own limit: the largest distance from the true boundary to the nearest
  // sample (in the sparse half).
  const NearestIndex index(points);
  double gap = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const double t = k / 4000.0, a = 2 * M_PI * t;
    for (const Point3& q : {Point3(t, 0, 0), Point3(t, 1, 0), Point3(0, t, 0), Point3(1, t, 0),
                            Point3(0.5 + kHoleRadius * std::cos(a), 0.5 + kHoleRadius * std::sin(a), 0)})
      gap = std::max(gap, index.nearest(q).second);
  }
  const double sparse = result.spacing * std::sqrt(10.0);
  std::cout << "true boundary to the nearest sample: up to " << gap / sparse << " sparse spacings\n";
  for (const BoundaryCurve& curve : result.curves) {
    double worst = 0.0, xmin = 1, xmax = 0;
    Point3 where;
    for (const BoundaryVertex& v : curve.vertices) {
      if (to_true_boundary(v.position) > worst) worst = to_true_boundary(v.position), where = v.position;
      xmin = std::min(xmin, v.position.x());
      xmax = std::max(xmax, v.position.x());
    }
    std::cout << "curve x " << xmin << ".." << xmax << ": farthest from the true boundary " << worst / sparse
              << " sparse spacings at " << where << "\n";
    EXPECT_LT(xmin, 0.35);
    EXPECT_GT(xmax, 0.65);
    // Measured 1.52 and 1.94 sparse spacings, against a sampling gap of 1.75.
    EXPECT_LT(worst, 1.25 * gap);
  }
  // Linked in the average spacing (the default), the sparse half's rims fall into pieces.
  boundary::BoundaryOptions steps_only;
  steps_only.drop_density_steps = true;
  const auto global = boundary::detect_boundary(points, normals, steps_only);
  std::size_t whole = 0;
  for (const BoundaryCurve& curve : global.curves) {
    double xmin = 1, xmax = 0;
    for (const BoundaryVertex& v : curve.vertices) xmin = std::min(xmin, v.position.x()), xmax = std::max(xmax, v.position.x());
    if (xmin < 0.35 && xmax > 0.65) ++whole;
  }
  std::cout << "linked in the average spacing: " << global.curves.size() << " curves, " << whole
            << " through both halves, " << global.dropped_loops << " loops dropped\n";
  EXPECT_LT(whole, 2u);
  // No sample along the step is a boundary point.
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (result.is_boundary_point[i] && std::abs(p.x() - 0.5) < 0.02) {
      EXPECT_LT(to_true_boundary(p), 2.0 * sparse) << p;
    }
  }
  // Without the step test the dense half's samples along the step are flagged and linked.
  boundary::BoundaryOptions keep_steps = local;
  keep_steps.drop_density_steps = false;
  const auto with_steps = boundary::detect_boundary(points, normals, keep_steps);
  std::size_t on_step = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (with_steps.is_boundary_point[i] && to_true_boundary(points[i]) > 2.0 * sparse) ++on_step;
  std::cout << "with the step kept: " << with_steps.curves.size() << " curves, " << on_step
            << " boundary points away from the true boundary\n";
  EXPECT_GT(on_step, 20u);
}

}  // namespace
}  // namespace envcrust
