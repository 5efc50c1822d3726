// libFuzzer harness of the CSV point reader (commas, header names): points, then normal estimation, and as a closed curve.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".csv", data, size, envcrust::fuzz::read_points_and_curve);
}
