// Input and option checks of power_crust: finiteness, duplicates, dimension, option ranges.
#include "stages.h"

#include "envcrust/errors.h"

#include <tbb/parallel_sort.h>

#include <cmath>
#include <numeric>
#include <sstream>
#include <tuple>

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
  if (!(options.bounding_box_scale > 1.0) || !std::isfinite(options.bounding_box_scale))
    throw InvalidOptions("PowerCrustOptions.bounding_box_scale must be a finite number > 1 (got " +
                         format_value(options.bounding_box_scale) + ")");
  Thresholds t;
  if (options.preset == LabelPreset::Readme) t = {0.4, 0.3};
  if (options.neighbor_threshold)
    t.neighbor = check_unit_range("neighbor_threshold", *options.neighbor_threshold);
  if (options.second_pass_threshold)
    t.second_pass = check_unit_range("second_pass_threshold", *options.second_pass_threshold);
  return t;
}

MergedSamples merge_duplicates(const std::vector<Point3>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw InvalidInput("point " + std::to_string(i) + " has a non-finite coordinate");
  }
  // Sorting indices with the index as last key gives each group of equal points its first
  // occurrence as representative, whatever the sort's thread schedule.
  std::vector<Index> order(points.size());
  std::iota(order.begin(), order.end(), Index{0});
  tbb::parallel_sort(order.begin(), order.end(), [&](Index a, Index b) {
    const Point3& p = points[a];
    const Point3& q = points[b];
    return std::make_tuple(p.x(), p.y(), p.z(), a) < std::make_tuple(q.x(), q.y(), q.z(), b);
  });
  std::vector<Index> representative(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const bool same = k > 0 && points[order[k]] == points[order[k - 1]];
    representative[order[k]] = same ? representative[order[k - 1]] : order[k];
  }
  MergedSamples out;
  out.input_to_sample.resize(points.size());
  out.samples.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (representative[i] == i) {
      out.input_to_sample[i] = static_cast<Index>(out.samples.size());
      out.samples.push_back(points[i]);
    } else {
      out.input_to_sample[i] = out.input_to_sample[representative[i]];
    }
  }
  out.duplicates = points.size() - out.samples.size();
  return out;
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
