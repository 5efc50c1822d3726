// Groups of boundary candidates whose neighbourhoods are no sheet: the angle-gap test reads the
// neighbours' directions in a tangent plane, which only a neighbourhood lying near one plane
// has. Around a tube a few spacings thick (a tail, a horn, a thin rod), a tip or a crumpled
// part thinner than the sampling resolves, the neighbours wrap round, their projection leaves
// a gap, and a closed shape gets a short false loop that the envelope and sheet then follow.
#include "boundary_detail.h"

#include "envcrust/median.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace envcrust::boundary::detail {
namespace {

// The median thickness of a cloud is read on about this many of its points.
constexpr std::size_t kCloudProbes = 1000;

// Root of the smallest over the middle eigenvalue of the covariance of a point and its
// neighbours: the spread off their best plane over the spread across it, 0 on a plane and
// about 1 for a ball.
double thickness(const std::vector<Point3>& points, std::size_t i, std::span<const std::uint32_t> neighbors) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  auto at = [&](std::size_t j) { return Eigen::Vector3d(points[j].x(), points[j].y(), points[j].z()); };
  mean += at(i);
  for (const std::uint32_t j : neighbors) mean += at(j);
  mean /= static_cast<double>(neighbors.size() + 1);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  auto add = [&](std::size_t j) {
    const Eigen::Vector3d d = at(j) - mean;
    covariance += d * d.transpose();
  };
  add(i);
  for (const std::uint32_t j : neighbors) add(j);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d values = solver.eigenvalues();  // ascending
  if (!(values[1] > 0)) return 0.0;
  return std::sqrt(std::max(0.0, values[0]) / values[1]);
}

}  // namespace

std::size_t drop_thick_groups(const std::vector<Point3>& points, const NeighbourTable& table, std::size_t neighbors,
                              std::vector<std::vector<std::size_t>>& components, std::size_t& dropped_points) {
  const std::size_t k = std::min<std::size_t>(neighbors, table.k());
  auto of = [&](std::size_t i) { return table.of(i).first(k); };
  std::vector<double> cloud;
  const std::size_t stride = std::max<std::size_t>(1, points.size() / kCloudProbes);
  for (std::size_t i = 0; i < points.size(); i += stride) cloud.push_back(thickness(points, i, of(i)));
  const double limit = std::max(kMaxGroupThickness, kMaxGroupThicknessRelCloud * upper_median(std::move(cloud)));
  std::size_t dropped = 0;
  dropped_points = 0;
  std::erase_if(components, [&](const std::vector<std::size_t>& component) {
    std::vector<double> own;
    own.reserve(component.size());
    for (const std::size_t i : component) own.push_back(thickness(points, i, of(i)));
    if (!(upper_median(std::move(own)) > limit)) return false;
    ++dropped;
    dropped_points += component.size();
    return true;
  });
  return dropped;
}

}  // namespace envcrust::boundary::detail
