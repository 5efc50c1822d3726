// Bad scenes are refused with one-line messages naming the layer and the element.
#include "scenes.h"

#include "envcrust/errors.h"

#include <gtest/gtest.h>

#include <limits>

namespace envcrust::render {
namespace {

template <class E>
void expect_error(const Scene& scene, const std::string& message) {
  EXPECT_EQ(testing::message_of<E>([&] { render_scene(scene, testing::small_options(32, 32)); }), message);
}

TriangleMesh triangle() {
  return {{Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)}, {{0, 1, 2}}};
}

TEST(PreparedScene, empty_scene_is_refused) {
  expect_error<InvalidInput>(Scene{}, "render: the scene is empty (no triangle, sphere or loop): nothing to draw");
  Scene no_triangles;
  no_triangles.meshes.push_back({TriangleMesh{{Point3(0, 0, 0)}, {}}});
  expect_error<InvalidInput>(no_triangles,
                             "render: the scene is empty (no triangle, sphere or loop): nothing to draw");
}

TEST(PreparedScene, non_finite_coordinates_are_refused) {
  Scene scene;
  scene.meshes.push_back({triangle()});
  scene.meshes[0].mesh.vertices[1] = Point3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  expect_error<InvalidInput>(scene, "render: mesh 0 vertex 1 has a non-finite coordinate");
  Scene balls;
  balls.spheres.push_back({{Point3(0, 0, 0), Point3(0, std::numeric_limits<double>::infinity(), 0)}, {}});
  expect_error<InvalidInput>(balls, "render: sphere layer 0 centre 1 has a non-finite coordinate");
}

TEST(PreparedScene, triangle_index_out_of_range_is_refused) {
  Scene scene;
  scene.meshes.push_back({triangle()});
  scene.meshes.push_back({triangle()});
  scene.meshes[1].mesh.triangles.push_back({0, 1, 7});
  expect_error<InvalidInput>(scene, "render: mesh 1 triangle 1 has vertex index 7, but the mesh has 3 vertices");
}

TEST(PreparedScene, bad_radii_and_opacity_are_refused) {
  Scene counts;
  counts.spheres.push_back({{Point3(0, 0, 0), Point3(1, 0, 0), Point3(2, 0, 0)}, {0.1, 0.2}});
  expect_error<InvalidInput>(counts, "render: sphere layer 0 has 2 radii for 3 centres (expected 0, 1 or one per centre)");
  Scene negative;
  negative.spheres.push_back({{Point3(0, 0, 0)}, {-1.0}});
  expect_error<InvalidInput>(negative, "render: sphere layer 0 radius 0 must be finite and > 0 (got -1)");
  Scene invisible;
  invisible.spheres.push_back({{Point3(0, 0, 0)}, {1.0}, {}, 0.0f});
  expect_error<InvalidInput>(invisible, "render: sphere layer 0 opacity must be in (0, 1] (got 0)");
  Scene tube;
  tube.curves.push_back({{{Point3(0, 0, 0), Point3(1, 0, 0)}}, -0.5, {}});
  expect_error<InvalidInput>(tube, "render: curve layer 0 radius must be finite and >= 0 (got -0.5)");
}

TEST(PreparedScene, loop_with_one_point_is_refused) {
  Scene scene;
  scene.curves.push_back({{{Point3(0, 0, 0), Point3(1, 0, 0)}, {Point3(0, 0, 0)}}, 0.0, {}});
  expect_error<InvalidInput>(scene, "render: curve layer 0 loop 1 needs at least 2 points (got 1)");
}

TEST(PreparedScene, a_single_point_without_radius_is_degenerate) {
  Scene scene;
  scene.spheres.push_back({{Point3(1, 2, 3), Point3(1, 2, 3)}, {}});
  expect_error<DegenerateInput>(scene, "render: the scene has zero extent (all points coincide and no radius)");
  scene.spheres[0].radii = {0.5};  // with a radius the ball is drawn
  EXPECT_GT(testing::covered_pixels(render_scene(scene, testing::small_options(32, 32))), 0u);
}

TEST(PreparedScene, far_away_coordinates_render_like_centred_ones) {
  // The unit frame keeps Embree's single precision away from large offsets.
  Scene near, far;
  near.meshes.push_back({testing::unit_sphere(32, 16)});
  far.meshes.push_back({testing::unit_sphere(32, 16)});
  for (auto& p : far.meshes[0].mesh.vertices) p = Point3(p.x() + 1e7, p.y() - 1e7, p.z() + 1e7);
  const auto options = testing::small_options(64, 64, View::iso());
  const auto a = static_cast<double>(testing::covered_pixels(render_scene(near, options)));
  const auto b = static_cast<double>(testing::covered_pixels(render_scene(far, options)));
  EXPECT_GT(a, 500);
  EXPECT_NEAR(a, b, 2.0);
}

}  // namespace
}  // namespace envcrust::render
