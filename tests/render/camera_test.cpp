// The camera presets put the axes where View documents them: front has x right and z up,
// top has x right and y up, and azimuth 0 looks along -x with y to the right.
#include "scenes.h"

#include <gtest/gtest.h>

namespace envcrust::render {
namespace {

// Three balls on the axes: red on +x, green on +y, blue on +z, plus a grey one at the origin.
Scene axes_scene() {
  Scene scene;
  scene.spheres.push_back({{Point3(1, 0, 0)}, {0.25}, {1, 0, 0}});
  scene.spheres.push_back({{Point3(0, 1, 0)}, {0.25}, {0, 1, 0}});
  scene.spheres.push_back({{Point3(0, 0, 1)}, {0.25}, {0, 0, 1}});
  scene.spheres.push_back({{Point3(0, 0, 0), Point3(-1, -1, -1)}, {0.25}, {0.5, 0.5, 0.5}});
  return scene;
}

struct Offset {
  double right = 0, up = 0;  ///< centroid of the pixels dominated by a channel, from the centre
  double pixels = 0;
};

Offset offset_of(const Image& image, int channel) {
  Offset o;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = testing::pixel(image, x, y);
      const int other1 = p[(channel + 1) % 3], other2 = p[(channel + 2) % 3];
      if (p[channel] > other1 + 40 && p[channel] > other2 + 40) {
        o.right += x + 0.5 - image.width / 2.0;
        o.up += image.height / 2.0 - (y + 0.5);
        o.pixels += 1;
      }
    }
  }
  if (o.pixels > 0) o.right /= o.pixels, o.up /= o.pixels;
  return o;
}

TEST(Camera, front_view_has_x_right_and_z_up) {
  const Image image = render_scene(axes_scene(), testing::small_options(120, 120, View::front()));
  const Offset red = offset_of(image, 0), blue = offset_of(image, 2);
  ASSERT_GT(red.pixels, 0);
  ASSERT_GT(blue.pixels, 0);
  EXPECT_GT(red.right, 20);
  EXPECT_NEAR(red.up, 0.0, 1.0);  // the box is centred on the origin: axes through the centre
  EXPECT_GT(blue.up, 20);
  EXPECT_NEAR(blue.right, 0.0, 1.0);
}

TEST(Camera, top_view_has_x_right_and_y_up) {
  const Image image = render_scene(axes_scene(), testing::small_options(120, 120, View::top()));
  const Offset red = offset_of(image, 0), green = offset_of(image, 1);
  EXPECT_GT(red.right, 20);
  EXPECT_NEAR(red.up, 0.0, 1.0);
  EXPECT_GT(green.up, 20);
  EXPECT_NEAR(green.right, 0.0, 1.0);
}

TEST(Camera, azimuth_zero_looks_along_minus_x_with_y_right) {
  const Image image = render_scene(axes_scene(), testing::small_options(120, 120, View{0.0, 0.0}));
  const Offset green = offset_of(image, 1), blue = offset_of(image, 2);
  const Offset red = offset_of(image, 0);
  EXPECT_GT(green.right, 20);
  EXPECT_GT(blue.up, 20);
  ASSERT_GT(red.pixels, 0);  // red, at +x, faces the camera in the middle
  EXPECT_NEAR(red.right, 0.0, 1.0);
  EXPECT_NEAR(red.up, 0.0, 1.0);
}

}  // namespace
}  // namespace envcrust::render
