// An 8-bit RGB image in memory: what `render` makes and `io` encodes as PNG.
#pragma once

#include <cstdint>
#include <vector>

namespace envcrust::render {

/// An 8-bit RGB image, rows top to bottom, 3 bytes per pixel (sRGB values).
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes
};

}  // namespace envcrust::render
