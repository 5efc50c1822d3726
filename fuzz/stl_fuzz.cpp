// libFuzzer harness of the STL reader (ascii and binary): the file as a mesh, then the analyzer, and as points, then normal estimation.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".stl", data, size, envcrust::fuzz::read_mesh_and_points);
}
