// Lighting in linear light, encoded to sRGB at the end, so that shading falls off evenly.
#include "shading.h"

#include <algorithm>
#include <cmath>

namespace envcrust::render::detail {
namespace {

// Light weights: ambient keeps faces turned away readable; headlight + key sum to about 1 at
// a face seen head-on, so the given colour comes out at its own brightness there.
constexpr double kAmbient = 0.12;
constexpr double kHeadlight = 0.45;
constexpr double kKey = 0.55;
constexpr double kSpecular = 0.18;
constexpr double kShininess = 48.0;

double srgb_to_linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

Rgb to_linear(Color color) {
  return {srgb_to_linear(color.r), srgb_to_linear(color.g), srgb_to_linear(color.b)};
}

std::uint8_t to_srgb_byte(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(255.0 * s));
}

Lights make_lights(Vec3 right, Vec3 up, Vec3 forward) {
  Lights lights;
  lights.view = -forward;
  lights.key = normalized(lights.view + 0.7 * up - 0.6 * right);
  lights.key_half = normalized(lights.key + lights.view);
  return lights;
}

Rgb shade(Rgb base, Vec3 normal, const Lights& lights) {
  const double diffuse = kAmbient + kHeadlight * std::max(0.0, dot(normal, lights.view)) +
                         kKey * std::max(0.0, dot(normal, lights.key));
  const double highlight =
      kSpecular * std::pow(std::max(0.0, dot(normal, lights.key_half)), kShininess);
  return diffuse * base + Rgb{highlight, highlight, highlight};
}

}  // namespace envcrust::render::detail

namespace envcrust::render {

Color heat_color(double t) {
  // Blue, cyan, green, yellow, red at t = 0, 1/4, 1/2, 3/4, 1, linear between (in sRGB).
  static constexpr Color kStops[] = {{0.15f, 0.30f, 0.90f}, {0.10f, 0.75f, 0.85f}, {0.20f, 0.75f, 0.25f},
                                     {0.95f, 0.85f, 0.15f}, {0.85f, 0.15f, 0.10f}};
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  const double at = t * 4.0;
  const auto k = std::min<std::size_t>(3, static_cast<std::size_t>(at));
  const auto f = static_cast<float>(at - static_cast<double>(k));
  const Color& a = kStops[k];
  const Color& b = kStops[k + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

}  // namespace envcrust::render
