// Shared helpers of the Power Crust tests: sampled builtins and the crust's measured quality.
#pragma once

#include "envcrust/distance.h"
#include "envcrust/power_crust.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"

#include <string>
#include <vector>

namespace envcrust::powercrust::test_support {

/// Points on a builtin surface, Gaussian noise as a fraction of the bbox diagonal.
inline std::vector<Point3> sample_builtin(const std::string& name, std::size_t count, double noise,
                                          std::uint64_t seed = 7) {
  const auto surface = surfaces::make_builtin(name);
  surfaces::SampleOptions options;
  options.count = count;
  options.noise_rel_diag = noise;
  options.seed = seed;
  return surfaces::sample_surface(*surface, options).points;
}

/// Two-sided Hausdorff distance of the crust to the builtin's exact tessellation, as a
/// fraction of the tessellation's bbox diagonal.
inline double relative_hausdorff(const TriangleMesh& crust, const std::string& name) {
  const auto surface = surfaces::make_builtin(name);
  const TriangleMesh truth = surfaces::tessellate(*surface);
  distance::DistanceOptions options;
  options.samples = 20000;
  const auto report = distance::compare_to_mesh(crust, truth, options);
  return report.relative(report.hausdorff);
}

}  // namespace envcrust::powercrust::test_support
