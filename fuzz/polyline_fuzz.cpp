// libFuzzer harness of the polyline reader (.polyline, one point per line or CGAL's "n x1 y1 z1 ..."):
// the closed curve, then the knot analysis of a short one.
#include "fuzz_support.h"

namespace {

void read_curve(const std::filesystem::path& path) {
  using namespace envcrust;
  Polyline curve;
  if (!fuzz::try_read(path, [&] { curve = io::read_polyline(path); })) return;
  if (curve.size() < 3) fuzz::broken("a closed curve of fewer than 3 points");
  fuzz::check_coordinates(curve);
  if (curve.size() > fuzz::max_curve_points) return;
  try {
    (void)analysis::analyze_curve(curve);
  } catch (const Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return envcrust::fuzz::run_input(".polyline", data, size, read_curve);
}
