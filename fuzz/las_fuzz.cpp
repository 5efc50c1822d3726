// libFuzzer harness of the LAS reader: the file as points (positions scaled and offset, colours,
// intensity and classification), then normal estimation.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".las", data, size, envcrust::fuzz::read_points);
}
