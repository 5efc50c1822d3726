// Narrow inlets cut off detected curves (close_inlets): a detour of the curve into the
// surface through a narrow mouth is cut across the mouth; a tongue of the surface, the two
// sides of a narrow hole and a notch too long to be a void stay.
#include "boundary_detail.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace envcrust {
namespace {

using boundary::detail::close_inlets;

// A closed curve in the plane z = 0 through the given corners, sampled every 0.1 (unit
// spacing s = 0.1), counter-clockwise, with outward conormals (to the right of the tangent).
BoundaryCurve polygon(const std::vector<std::pair<double, double>>& corners) {
  BoundaryCurve curve;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const auto [x0, y0] = corners[k];
    const auto [x1, y1] = corners[(k + 1) % corners.size()];
    const double len = std::hypot(x1 - x0, y1 - y0);
    const auto steps = static_cast<int>(std::round(len / 0.1));
    const Vector3 t((x1 - x0) / len, (y1 - y0) / len, 0);
    for (int i = 0; i < steps; ++i) {
      BoundaryVertex v;
      v.position = Point3(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps, 0);
      v.tangent = t;
      v.normal = Vector3(0, 0, 1);
      v.conormal = Vector3(t.y(), -t.x(), 0);
      curve.vertices.push_back(v);
    }
  }
  return curve;
}

double lowest_y_near(const Polyline& curve, double x, double above) {
  double low = 1e9;
  for (const Point3& p : curve)
    if (std::abs(p.x() - x) < 0.05 && p.y() > above) low = std::min(low, p.y());
  return low;
}

double highest_y_near(const Polyline& curve, double x) {
  double high = -1e9;
  for (const Point3& p : curve)
    if (std::abs(p.x() - x) < 0.05) high = std::max(high, p.y());
  return high;
}

// A 4 x 2 rectangle (the surface) whose top edge y = 2 runs into a slot at x = 2: 0.3 wide,
// 0.6 deep (loop with its mouth 1.8 = 18 s).
TEST(Inlets, ASlotBesideTheRimIsCutAcrossItsMouth) {
  const BoundaryCurve curve = polygon({{0, 0}, {4, 0}, {4, 2}, {2.15, 2}, {2.15, 1.4}, {1.85, 1.4}, {1.85, 2}, {0, 2}});
  std::size_t closed = 0;
  const Polyline out = close_inlets(curve, 2.0, closed);
  EXPECT_EQ(closed, 1u);
  EXPECT_NEAR(lowest_y_near(out, 2.0, 1.0), 2.0, 1e-9);  // straight across the mouth
  // Longer than the loop limit: kept.
  std::size_t none = 0;
  const Polyline kept = close_inlets(curve, 1.5, none);
  EXPECT_EQ(none, 0u);
  EXPECT_NEAR(lowest_y_near(kept, 2.0, 1.0), 1.4, 1e-9);
}

// The same rectangle with a tongue 0.3 wide sticking 0.6 out of its top edge: surface, kept.
TEST(Inlets, ATongueOfTheSurfaceStays) {
  const BoundaryCurve curve = polygon({{0, 0}, {4, 0}, {4, 2}, {2.15, 2}, {2.15, 2.6}, {1.85, 2.6}, {1.85, 2}, {0, 2}});
  std::size_t closed = 0;
  const Polyline out = close_inlets(curve, 2.0, closed);
  EXPECT_EQ(closed, 0u);
  EXPECT_NEAR(highest_y_near(out, 2.0), 2.6, 1e-9);
}

// A narrow hole (a slot 0.2 wide, 1.2 long, its conormals pointing into it): its ends are not
// inlets of it, nothing is cut.
TEST(Inlets, TheSidesOfANarrowHoleAreNoMouth) {
  // Clockwise, so that the conormals (right of the tangent) point into the hole.
  const BoundaryCurve curve = polygon({{0, 0}, {0, 0.2}, {1.2, 0.2}, {1.2, 0}});
  std::size_t closed = 0;
  const Polyline out = close_inlets(curve, 2.0, closed);
  EXPECT_EQ(closed, 0u);
  EXPECT_EQ(out.size(), curve.vertices.size());
}

// An L-shaped surface: its inner corner (conormals 90 degrees apart either side) stays.
TEST(Inlets, AnInnerCornerIsNoInlet) {
  const BoundaryCurve curve = polygon({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}});
  std::size_t closed = 0;
  close_inlets(curve, 2.0, closed);
  EXPECT_EQ(closed, 0u);
}

}  // namespace
}  // namespace envcrust

namespace envcrust {
namespace {

// The rim of a thin tube (a circle of radius 0.3 about z = 0, 19 vertices 0.1 apart) whose
// conormals all point along the tube (+z): every stretch of it passes the conormal test and a
// half circle's mouth is 0.64 of its arc, but none lies inward of its mouth: nothing is cut.
TEST(Inlets, AThinTubesRimIsNoInlet) {
  BoundaryCurve curve;
  const int n = 19;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    BoundaryVertex v;
    v.position = Point3(0.3 * std::cos(a), 0.3 * std::sin(a), 0.003 * std::cos(3 * a));  // a little noise
    v.tangent = Vector3(-std::sin(a), std::cos(a), 0);
    v.normal = Vector3(std::cos(a), std::sin(a), 0);
    v.conormal = Vector3(0, 0, 1);
    curve.vertices.push_back(v);
  }
  std::size_t closed = 0;
  const Polyline out = boundary::detail::close_inlets(curve, 10.0, closed);
  EXPECT_EQ(closed, 0u);
  EXPECT_EQ(out.size(), curve.vertices.size());
}

}  // namespace
}  // namespace envcrust
