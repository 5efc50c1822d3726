// Portable seeded random numbers: std distributions differ between standard libraries, so the
// same seed would give different samples elsewhere; these transforms do not.
#pragma once

#include <cstdint>
#include <random>

namespace envcrust {

/// Uniform double in [0, 1) from the top 53 bits of one 64-bit draw.
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace envcrust
