// render_scene: silhouettes of known shapes cover their analytic projected areas, open
// surfaces show their back colour, translucency, determinism, option errors.
#include "scenes.h"

#include "envcrust/errors.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

namespace envcrust::render {
namespace {

using testing::covered_pixels;
using testing::small_options;
using testing::unit_sphere;

constexpr double kPi = std::numbers::pi;

Scene sphere_scene() {
  Scene scene;
  scene.meshes.push_back({unit_sphere()});
  return scene;
}

double covered_fraction(const Image& image) {
  return static_cast<double>(covered_pixels(image)) / (image.width * image.height);
}

TEST(RenderScene, image_has_the_requested_size) {
  const Image image = render_scene(sphere_scene(), small_options(120, 70));
  EXPECT_EQ(image.width, 120);
  EXPECT_EQ(image.height, 70);
  EXPECT_EQ(image.rgb.size(), 120u * 70u * 3u);
}

// The box [-1,1]^3 seen from the front projects to a 2 x 2 square that spans 90% (margin
// 0.05) of the tighter side: the sphere's disk has radius 0.45 * min(W, H) pixels.
TEST(RenderScene, unit_sphere_from_the_front_covers_the_analytic_disk) {
  const Image square = render_scene(sphere_scene(), small_options(200, 200));
  EXPECT_NEAR(covered_fraction(square), kPi * 0.45 * 0.45, 0.004);  // 0.6362
  const Image wide = render_scene(sphere_scene(), small_options(240, 160));
  EXPECT_NEAR(covered_fraction(wide), kPi * 72.0 * 72.0 / (240.0 * 160.0), 0.004);  // 0.4241
}

// Iso view (az 45, el 30): the cube's corners project to half-widths sqrt(2) along `right`
// and sin30 * sqrt(2) + cos30 = 1.5731 along `up`; the larger fills 90% of the image, so the
// disk radius is 0.9 * W / (2 * 1.5731) = 0.28605 W.
TEST(RenderScene, unit_sphere_in_iso_view_covers_the_analytic_disk) {
  const Image image = render_scene(sphere_scene(), small_options(200, 200, View::iso()));
  const double radius = 0.9 / (2 * (0.5 * std::sqrt(2.0) + std::sqrt(3.0) / 2));
  EXPECT_NEAR(covered_fraction(image), kPi * radius * radius, 0.004);  // 0.2571
}

TEST(RenderScene, unit_sphere_is_centred) {
  const Image image = render_scene(sphere_scene(), small_options(160, 120, View::iso()));
  double sx = 0, sy = 0, n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!testing::is_black(image, x, y)) sx += x + 0.5, sy += y + 0.5, n += 1;
  ASSERT_GT(n, 0);
  EXPECT_NEAR(sx / n, 80.0, 0.3);
  EXPECT_NEAR(sy / n, 60.0, 0.3);
}

TEST(RenderScene, sphere_points_cover_the_same_disk_as_the_mesh) {
  Scene scene;
  scene.spheres.push_back({{Point3(0, 0, 0)}, {1.0}});
  const Image image = render_scene(scene, small_options(200, 200));
  EXPECT_NEAR(covered_fraction(image), kPi * 0.45 * 0.45, 0.004);
}

// A ring of radius 1 drawn as a tube of radius 0.05 seen from the top: an annulus of area
// pi (1.05^2 - 0.95^2) = 0.2 pi in a box of half-width 1.05 that fills 90% of the image.
TEST(RenderScene, loop_tube_covers_the_analytic_annulus) {
  Scene scene;
  CurveLayer curves;
  curves.radius = 0.05;
  Polyline ring;
  for (int i = 0; i < 256; ++i) ring.emplace_back(std::cos(2 * kPi * i / 256), std::sin(2 * kPi * i / 256), 0.0);
  curves.loops.push_back(ring);
  scene.curves.push_back(curves);
  const Image image = render_scene(scene, small_options(200, 200, View::top()));
  const double box_side = 2 * 1.05 / 0.9;
  EXPECT_NEAR(covered_fraction(image), 0.2 * kPi / (box_side * box_side), 0.004);  // 0.1154
}

struct RedBlue {
  std::size_t red = 0, blue = 0;
};

RedBlue count_red_blue(const Image& image) {
  RedBlue count;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    if (image.rgb[i] > image.rgb[i + 2]) ++count.red;
    if (image.rgb[i + 2] > image.rgb[i]) ++count.blue;
  }
  return count;
}

// Looking into the open cylinder from above (iso view), the far inner wall shows through the
// top opening in the back colour. The far wall point (-0.707, -0.707, 0.9) projects onto
// `right` at 0 and onto `up` at 1.279: pixel (80, 80 - 1.279 / (3.1463 / 144)) = (80, 21.5);
// the top rim spans rows 17.5 to 63.3 of the centre column.
TEST(RenderScene, open_cylinder_shows_its_back_colour_inside) {
  Scene scene;
  scene.meshes.push_back({fixtures::open_cylinder(), {0, 0, 1}, {1, 0, 0}});
  const Image image = render_scene(scene, small_options(160, 160, View::iso()));
  for (const int y : {24, 40, 58}) {
    const auto* p = testing::pixel(image, 80, y);
    EXPECT_GT(p[0], p[2]) << "row " << y;
  }
  const auto* outside = testing::pixel(image, 80, 100);  // the outer front wall
  EXPECT_GT(outside[2], outside[0]);
  const RedBlue count = count_red_blue(image);
  EXPECT_GT(count.red, count.blue / 10);

  Scene closed;
  closed.meshes.push_back({unit_sphere(), {0, 0, 1}, {1, 0, 0}});
  EXPECT_EQ(count_red_blue(render_scene(closed, small_options(160, 160, View::iso()))).red, 0u);
}

TEST(RenderScene, translucent_ball_lets_the_background_through) {
  Scene opaque, translucent;
  opaque.spheres.push_back({{Point3(0, 0, 0)}, {1.0}, {1, 1, 1}, 1.0f});
  translucent.spheres.push_back({{Point3(0, 0, 0)}, {1.0}, {1, 1, 1}, 0.3f});
  const auto options = small_options(64, 64);
  const std::uint8_t full = testing::pixel(render_scene(opaque, options), 32, 32)[1];
  const std::uint8_t faint = testing::pixel(render_scene(translucent, options), 32, 32)[1];
  EXPECT_GT(faint, 0);
  EXPECT_LT(faint, full);
}

TEST(RenderScene, flat_shading_and_wireframe_change_the_picture) {
  Scene smooth = sphere_scene();
  Scene flat = sphere_scene();
  flat.meshes[0].shading = Shading::Flat;
  Scene wire = sphere_scene();
  wire.meshes[0].use_wireframe = true;
  const auto options = small_options(96, 96, View::iso());
  const Image a = render_scene(smooth, options);
  EXPECT_NE(a.rgb, render_scene(flat, options).rgb);
  EXPECT_NE(a.rgb, render_scene(wire, options).rgb);
  EXPECT_EQ(covered_pixels(a), covered_pixels(render_scene(flat, options)));
}

Scene mixed_scene() {
  Scene scene;
  scene.meshes.push_back({fixtures::moebius()});
  scene.spheres.push_back({{Point3(0, 0, 0), Point3(0.5, 0, 0)}, {0.3, 0.2}, {0.2, 0.4, 0.8}, 0.4f});
  CurveLayer curves;
  curves.loops.push_back({Point3(-1, -1, 0), Point3(1, -1, 0), Point3(1, 1, 0), Point3(-1, 1, 0)});
  scene.curves.push_back(curves);
  return scene;
}

TEST(RenderScene, same_scene_gives_the_same_bytes_at_any_thread_count) {
  RenderOptions options;
  options.width = 120;
  options.height = 90;
  const Image first = render_scene(mixed_scene(), options);
  EXPECT_EQ(first.rgb, render_scene(mixed_scene(), options).rgb);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(first.rgb, render_scene(mixed_scene(), options).rgb);
}

void expect_invalid_options(const RenderOptions& options, const std::string& message) {
  EXPECT_EQ(testing::message_of<InvalidOptions>([&] { render_scene(sphere_scene(), options); }), message);
}

TEST(RenderScene, options_out_of_range_are_refused_with_the_field_named) {
  RenderOptions o;
  o.width = 8;
  expect_invalid_options(o, "RenderOptions.width must be in [16, 8192] (got 8)");
  o = {};
  o.height = 9000;
  expect_invalid_options(o, "RenderOptions.height must be in [16, 8192] (got 9000)");
  o = {};
  o.supersampling = 0;
  expect_invalid_options(o, "RenderOptions.supersampling must be in [1, 4] (got 0)");
  o = {};
  o.margin = 0.5;
  expect_invalid_options(o, "RenderOptions.margin must be in [0, 0.45] (got 0.5)");
  o = {};
  o.view.elevation_deg = 100;
  expect_invalid_options(o, "RenderOptions.view.elevation_deg must be in [-90, 90] (got 100)");
}

}  // namespace
}  // namespace envcrust::render

namespace envcrust::render {
namespace {

// Vertex colours replace the front and back colours: a sphere whose vertices are all at the
// red end of the heat scale is drawn red, at the blue end blue; the scale runs blue, green,
// red and clamps outside [0, 1].
TEST(RenderScene, vertex_colours_paint_the_mesh) {
  auto painted = [](double t) {
    Scene scene;
    scene.meshes.push_back({unit_sphere()});
    scene.meshes[0].vertex_colors.assign(scene.meshes[0].mesh.vertices.size(), heat_color(t));
    return render_scene(scene, small_options(64, 64, View::front()));
  };
  const auto* red = testing::pixel(painted(1.0), 32, 32);
  EXPECT_GT(red[0], red[1] + 60);
  EXPECT_GT(red[0], red[2] + 60);
  const auto* blue = testing::pixel(painted(0.0), 32, 32);
  EXPECT_GT(blue[2], blue[0] + 60);
  EXPECT_GT(blue[2], blue[1] + 30);

  const Color green = heat_color(0.5);
  EXPECT_GT(green.g, green.r);
  EXPECT_GT(green.g, green.b);
  for (const auto& [outside, end] : {std::pair{-1.0, 0.0}, std::pair{7.0, 1.0}}) {
    EXPECT_EQ(heat_color(outside).r, heat_color(end).r);
    EXPECT_EQ(heat_color(outside).b, heat_color(end).b);
  }
}

TEST(RenderScene, vertex_colours_must_match_the_vertices) {
  Scene scene;
  scene.meshes.push_back({unit_sphere()});
  scene.meshes[0].vertex_colors = {heat_color(0), heat_color(1)};
  try {
    (void)render_scene(scene, small_options(32, 32, View::front()));
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "render: mesh 0 has 2 vertex colours for " +
                                         std::to_string(scene.meshes[0].mesh.vertices.size()) + " vertices");
  }
}

}  // namespace
}  // namespace envcrust::render
