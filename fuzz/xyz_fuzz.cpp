// libFuzzer harness of the text point reader (.xyz/.txt): points, then normal estimation, and the file as a closed curve.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".xyz", data, size, envcrust::fuzz::read_points_and_curve);
}
