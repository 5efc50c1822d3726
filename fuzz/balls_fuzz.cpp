// libFuzzer harness of the ball reader's text format ("x y z radius [label]" per line; its
// PLY form is fuzzed by ply_fuzz).
#include "fuzz_support.h"

namespace {

void read_balls(const std::filesystem::path& path) {
  using namespace envcrust;
  io::BallSet balls;
  if (!fuzz::try_read(path, [&] { balls = io::read_balls(path); })) return;
  fuzz::check_balls(balls);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".txt", data, size, read_balls);
}
