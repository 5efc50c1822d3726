// Tests of the local origin: an input far from (0, 0, 0) for its size (UTM-like coordinates)
// is prepared relative to a round origin near it and comes back exactly; near ones stay.
#include "fixtures/surface_samples.h"

#include "envcrust/input.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace envcrust {
namespace {

const Vector3 kUtm(500000.0, 5000000.0, 0.0);

std::vector<Point3> hemisphere_at(const Vector3& shift, std::size_t count = 1500) {
  std::vector<Point3> points = fixtures::builtin_samples("hemisphere", count).points;
  for (Point3& p : points) p = p + shift;
  return points;
}

input::PointInput as_input(std::vector<Point3> points) {
  input::PointInput in;
  in.points.points.points = std::move(points);
  return in;
}

TEST(LocalOrigin, points_at_utm_coordinates_are_prepared_relative_to_a_round_origin_near_them) {
  const Vector3 shift = kUtm + Vector3(0.3, 0.2, 0.4);
  input::PointInput in = as_input(hemisphere_at(shift));
  in.given_boundary = input::GivenBoundary{};
  for (const Point3& p : hemisphere_at(shift))
    if (p.z() - shift.z() < 0.02) in.given_boundary->points.points.push_back(p);
  const auto prepared = input::prepare_points(std::move(in));
  EXPECT_EQ(prepared.origin, kUtm);
  EXPECT_EQ(prepared.notes.front(), "coordinates taken relative to (500000, 5000000, 0): the input lies 1.67e+06 "
                                    "diagonals (2.99) from (0, 0, 0)");
  // The samples are the points minus the origin, and so is the rim given in the input's
  // coordinates: the curve runs near the rim circle (radius 1 about (0.3, 0.2, 0.4); the
  // fitted curve lies up to 0.06 inside it).
  for (const Point3& p : prepared.samples.points) EXPECT_LT(std::abs(p.x() - 0.3), 1.0 + 1e-9);
  ASSERT_EQ(prepared.samples.boundary.size(), 1u);
  for (const auto& v : prepared.samples.boundary[0].vertices)
    {
    EXPECT_NEAR(std::hypot(v.position.x() - 0.3, v.position.y() - 0.2), 1.0, 0.1);
    EXPECT_NEAR(v.position.z(), 0.4, 0.1);
  }
  std::vector<Point3> back = prepared.samples.points;
  input::restore_origin(back, prepared.origin);
  const auto original = hemisphere_at(shift);
  ASSERT_EQ(back.size(), original.size());
  for (std::size_t i = 0; i < back.size(); ++i) EXPECT_EQ(back[i], original[i]) << i;
}

TEST(LocalOrigin, points_within_100_diagonals_of_the_origin_keep_their_coordinates) {
  const Vector3 shift(200.0, -150.0, 30.0);  // 67 diagonals (2.99) away
  const auto prepared = input::prepare_points(as_input(hemisphere_at(shift)));
  EXPECT_EQ(prepared.origin, CGAL::NULL_VECTOR);
  EXPECT_EQ(prepared.samples.points, hemisphere_at(shift));
}

TEST(LocalOrigin, the_shift_can_be_turned_off) {
  input::InputOptions options;
  options.use_local_origin = false;
  const auto prepared = input::prepare_points(as_input(hemisphere_at(kUtm)), options);
  EXPECT_EQ(prepared.origin, CGAL::NULL_VECTOR);
  EXPECT_EQ(prepared.samples.points, hemisphere_at(kUtm));
}

TEST(LocalOrigin, a_mesh_far_from_the_origin_is_prepared_near_it) {
  TriangleMesh mesh;
  const double corners[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  for (const auto& c : corners) mesh.vertices.push_back(Point3(c[0], c[1], 0) + kUtm + Vector3(1, 1, 0));
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto prepared = input::prepare_mesh(mesh);
  EXPECT_EQ(prepared.origin, kUtm);
  ASSERT_EQ(prepared.samples.boundary.size(), 1u);
  for (const Point3& p : prepared.samples.points) {
    EXPECT_GE(p.x(), 1.0);
    EXPECT_LE(p.x(), 3.0);
  }
}

}  // namespace
}  // namespace envcrust
