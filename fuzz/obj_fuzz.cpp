// libFuzzer harness of the OBJ reader: the file as a mesh, then the analyzer, and as points (with colours), then normal estimation.
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".obj", data, size, envcrust::fuzz::read_mesh_and_points);
}
