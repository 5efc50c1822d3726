// Noise level of a point sample: the typical distance of points from the plane fitted to
// their neighbours.
#include "input_tree.h"

#include "envcrust/envelope.h"
#include "envcrust/errors.h"

#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace envcrust::envelope {
namespace {


// RMS distance of the neighbours to their least-squares plane: sqrt of the smallest
// eigenvalue of their covariance.
double plane_residual(const std::vector<Point3>& neighbours) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : neighbours) mean += Eigen::Vector3d(p.x(), p.y(), p.z());
  mean /= static_cast<double>(neighbours.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : neighbours) {
    const Eigen::Vector3d d = Eigen::Vector3d(p.x(), p.y(), p.z()) - mean;
    covariance += d * d.transpose();
  }
  covariance /= static_cast<double>(neighbours.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, solver.eigenvalues()(0)));
}

}  // namespace

double estimate_noise(const std::vector<Point3>& points, const NoiseOptions& options) {
  PointTree tree(points.begin(), points.end());
  tree.build();
  return estimate_noise(points, tree, options);
}

double estimate_noise(const std::vector<Point3>& points, const PointTree& tree, const NoiseOptions& options) {
  if (options.neighbors < 4)
    throw InvalidOptions("NoiseOptions::neighbors must be at least 4 (got " + std::to_string(options.neighbors) + ")");
  if (points.size() < 4) throw InvalidInput("noise: need at least 4 points");
  const auto k = static_cast<unsigned>(std::min<std::size_t>(options.neighbors, points.size()));
  // An even stride over the input: deterministic, and enough points for a median.
  const std::size_t stride = std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, options.max_points));
  const std::size_t count = (points.size() + stride - 1) / stride;
  std::vector<double> residual(count, 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 64), [&](const auto& range) {
    std::vector<Point3> neighbours;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      neighbours.clear();
      PointSearch search(tree, points[i * stride], k);
      for (const auto& [p, d2] : search) neighbours.push_back(p);
      residual[i] = plane_residual(neighbours);
    }
  });
  const auto middle = residual.begin() + static_cast<std::ptrdiff_t>(residual.size() / 2);
  std::nth_element(residual.begin(), middle, residual.end());
  return *middle;
}

}  // namespace envcrust::envelope
