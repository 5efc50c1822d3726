// Colour spaces and the lighting model: a headlight plus a key light from the upper left,
// Lambert diffuse and a weak Blinn highlight, in linear light.
#pragma once

#include "envcrust/render.h"
#include "vec3.h"

#include <cstdint>

namespace envcrust::render::detail {

/// A colour in linear light.
struct Rgb {
  double r = 0, g = 0, b = 0;
};

inline Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
inline Rgb operator*(double s, Rgb a) { return {s * a.r, s * a.g, s * a.b}; }

/// sRGB colour (as given by the user) to linear light.
Rgb to_linear(Color color);

/// Linear light in [0, 1] (clamped) to an 8-bit sRGB value.
std::uint8_t to_srgb_byte(double linear);

/// Light directions in the scene frame, derived from the camera frame.
struct Lights {
  Vec3 view;      ///< towards the camera (and the headlight)
  Vec3 key;       ///< towards the key light (upper left, in front)
  Vec3 key_half;  ///< Blinn half vector of key and view
};

Lights make_lights(Vec3 right, Vec3 up, Vec3 forward);

/// Lit colour of a surface point with unit normal `normal` facing the viewer.
Rgb shade(Rgb base, Vec3 normal, const Lights& lights);

}  // namespace envcrust::render::detail
