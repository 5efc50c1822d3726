// libFuzzer harness of the PTS point reader (Leica's point-count lines): points, then normal estimation, and as a closed curve.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".pts", data, size, envcrust::fuzz::read_points_and_curve);
}
