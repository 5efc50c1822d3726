// libFuzzer harness of the IGES reader (entities 128 and 144): the patches, then each small one made a surface.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".igs", data, size, envcrust::fuzz::read_nurbs);
}
