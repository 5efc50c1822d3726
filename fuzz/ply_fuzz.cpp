// libFuzzer harness of the PLY reader (ascii and binary): the file as a mesh, then the
// analyzer, as points, then normal estimation, and as balls (radius and label properties).
#include "fuzz_support.h"

namespace {

void read_ply(const std::filesystem::path& path) {
  envcrust::fuzz::read_mesh_and_points(path);
  envcrust::io::BallSet balls;
  if (envcrust::fuzz::try_read(path, [&] { balls = envcrust::io::read_balls(path); })) envcrust::fuzz::check_balls(balls);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".ply", data, size, read_ply);
}
