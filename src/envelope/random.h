// Portable seeded random numbers (std distributions differ between standard libraries).
#pragma once

#include <cstdint>
#include <random>

namespace envcrust::envelope {

inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace envcrust::envelope
