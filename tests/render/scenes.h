// Small scenes with known pictures for the render tests, and pixel-counting helpers.
#pragma once

#include "envcrust/render.h"
#include "fixtures/shapes.h"

#include <cmath>
#include <cstdint>
#include <exception>
#include <numbers>
#include <string>

namespace envcrust::render::testing {

/// UV sphere of radius 1 at the origin; its bounding box is [-1, 1]^3 exactly (nu is a
/// multiple of 4 and nv even, so the extreme points are vertices).
inline TriangleMesh unit_sphere(int nu = 96, int nv = 48) {
  return fixtures::grid_mesh(nu, nv, [](double u, double v) {
    const double phi = 2 * std::numbers::pi * u, theta = std::numbers::pi * v;
    return Point3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta));
  }, fixtures::Glue::Periodic);
}

inline RenderOptions small_options(int width, int height, View view = View::front()) {
  RenderOptions options;
  options.width = width;
  options.height = height;
  options.view = view;
  options.background = {0, 0, 0};
  options.supersampling = 1;  // a pixel is covered iff its centre ray hits: unbiased areas
  return options;
}

inline const std::uint8_t* pixel(const Image& image, int x, int y) {
  return &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
}

inline bool is_black(const Image& image, int x, int y) {
  const auto* p = pixel(image, x, y);
  return p[0] == 0 && p[1] == 0 && p[2] == 0;
}

/// Pixels that are not pure black (the test background).
inline std::size_t covered_pixels(const Image& image) {
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) count += is_black(image, x, y) ? 0 : 1;
  return count;
}

/// The message of the E thrown by `action`, or a description of what happened instead.
template <class E, class Action>
std::string message_of(Action&& action) {
  try {
    action();
  } catch (const E& error) {
    return error.what();
  } catch (const std::exception& error) {
    return std::string("unexpected exception: ") + error.what();
  }
  return "no exception";
}

}  // namespace envcrust::render::testing
