// Input and option checks of power_crust: dimension of the input, option ranges.
#include "stages.h"

#include "envcrust/errors.h"

#include <cmath>
#include <sstream>

namespace envcrust::powercrust {
namespace {

std::string format_value(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double check_unit_range(const char* field, double value) {
  if (!(value >= -1.0 && value <= 1.0))
    throw InvalidOptions(std::string("PowerCrustOptions.") + field + " must be in [-1, 1] (got " +
                         format_value(value) + ")");
  return value;
}

}  // namespace

Thresholds check_options(const PowerCrustOptions& options) {
  if (!(options.pole_joggle >= 0.0 && options.pole_joggle <= 1e-2))
    throw InvalidOptions("PowerCrustOptions.pole_joggle must be in [0, 1e-2] (got " +
                         format_value(options.pole_joggle) + ")");
  if (!(options.bounding_box_scale > 1.0 && options.bounding_box_scale <= 1000.0))
    throw InvalidOptions("PowerCrustOptions.bounding_box_scale must be in (1, 1000] (got " +
                         format_value(options.bounding_box_scale) + ")");
  if (!(options.min_pole_radius_rel_spacing >= 0.0) || !std::isfinite(options.min_pole_radius_rel_spacing))
    throw InvalidOptions("PowerCrustOptions.min_pole_radius_rel_spacing must be a finite number >= 0 (got " +
                         format_value(options.min_pole_radius_rel_spacing) + ")");
  Thresholds t;
  if (options.preset == LabelPreset::Readme) t = {0.4, 0.3, 0.6};
  if (options.sampling_estimate) {
    if (!(*options.sampling_estimate > 0.0 && *options.sampling_estimate <= 1.0))
      throw InvalidOptions("PowerCrustOptions.sampling_estimate must be in (0, 1] (got " +
                           format_value(*options.sampling_estimate) + ")");
    t.sampling_estimate = *options.sampling_estimate;
  }
  if (options.neighbor_threshold)
    t.neighbor = check_unit_range("neighbor_threshold", *options.neighbor_threshold);
  if (options.second_pass_threshold)
    t.second_pass = check_unit_range("second_pass_threshold", *options.second_pass_threshold);
  return t;
}

void check_dimension(const std::vector<Point3>& samples) {
  const std::size_t n = samples.size();
  if (n < 5)
    throw DegenerateInput("need at least 5 distinct points, got " + std::to_string(n));
  // Samples are distinct, so samples[0] and samples[1] span a line.
  std::size_t third = 2;
  while (third < n && CGAL::collinear(samples[0], samples[1], samples[third])) ++third;
  if (third == n)
    throw DegenerateInput("all " + std::to_string(n) + " points are collinear: nothing to reconstruct");
  std::size_t fourth = 2;
  while (fourth < n &&
         CGAL::orientation(samples[0], samples[1], samples[third], samples[fourth]) == CGAL::COPLANAR)
    ++fourth;
  if (fourth == n)
    throw DegenerateInput("all " + std::to_string(n) + " points are coplanar: nothing to reconstruct");
}

}  // namespace envcrust::powercrust
