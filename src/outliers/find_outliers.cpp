// Stray samples: off their neighbours' plane, or far from every other point.
#include "envcrust/outliers.h"

#include "envcrust/errors.h"
#include "envcrust/median.h"
#include "envcrust/mesh.h"
#include "envcrust/neighbour_table.h"

#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace envcrust::outliers {
namespace {

void validate(const OutlierOptions& o) {
  auto fail = [](const char* field, double value) {
    throw InvalidOptions(std::string("OutlierOptions::") + field + " out of range: " + std::to_string(value));
  };
  if (o.neighbors < 6) fail("neighbors", o.neighbors);
  if (!(o.off_plane_rel_radius > 0 && o.off_plane_rel_radius <= 1)) fail("off_plane_rel_radius", o.off_plane_rel_radius);
  if (!(o.off_plane_rel_noise > 0)) fail("off_plane_rel_noise", o.off_plane_rel_noise);
  if (!(o.isolated_rel_spacing > 1)) fail("isolated_rel_spacing", o.isolated_rel_spacing);
}

// What one point's neighbourhood says about it.
struct Local {
  double off_plane = 0;   // distance of the point to its neighbours' plane
  double radius = 0;      // distance to the farthest neighbour
  double mean_distance = 0;
  double residual = 0;    // robust spread of the neighbours about their plane (1.4826 MAD)
};

Local fit(const Point3& p, const std::vector<Point3>& points, const std::uint32_t* neighbours, unsigned k,
          std::vector<double>& scratch) {
  Local out;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (unsigned j = 0; j < k; ++j) {
    const Point3& q = points[neighbours[j]];
    mean += Eigen::Vector3d(q.x(), q.y(), q.z());
    const double d = std::sqrt(CGAL::squared_distance(p, q));
    out.radius = std::max(out.radius, d);
    out.mean_distance += d / k;
  }
  mean /= static_cast<double>(k);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (unsigned j = 0; j < k; ++j) {
    const Point3& q = points[neighbours[j]];
    const Eigen::Vector3d d = Eigen::Vector3d(q.x(), q.y(), q.z()) - mean;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);
  out.off_plane = std::abs(normal.dot(Eigen::Vector3d(p.x(), p.y(), p.z()) - mean));
  scratch.clear();
  for (unsigned j = 0; j < k; ++j) {
    const Point3& q = points[neighbours[j]];
    scratch.push_back(std::abs(normal.dot(Eigen::Vector3d(q.x(), q.y(), q.z()) - mean)));
  }
  out.residual = 1.4826 * upper_median_in_place(scratch);
  return out;
}

}  // namespace

OutlierReport find_outliers(const std::vector<Point3>& points, const OutlierOptions& options) {
  validate(options);
  if (points.size() <= options.neighbors) return find_outliers(points, NeighbourTable(), options);
  return find_outliers(points, NeighbourTable(points, options.neighbors), options);
}

OutlierReport find_outliers(const std::vector<Point3>& points, const NeighbourTable& table,
                            const OutlierOptions& options) {
  validate(options);
  OutlierReport report;
  const std::size_t n = points.size();
  report.is_outlier.assign(n, 0);
  const unsigned k = options.neighbors;
  if (n <= k) return report;
  if (table.size() != n || table.k() < k) {
    throw InvalidOptions("find_outliers: a neighbour table of " + std::to_string(table.size()) + " rows of " +
                         std::to_string(table.k()) + " for " + std::to_string(n) + " points and " +
                         std::to_string(k) + " neighbours");
  }
  // Rows in the table's Hilbert order: consecutive fits read the same points (in a scan's
  // file order, each distance read was a cache miss). The result does not depend on threads.
  const std::vector<std::size_t>& order = table.order();
  std::vector<Local> local(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
    std::vector<double> scratch;
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      const std::size_t i = order[r];
      local[i] = fit(points[i], points, table.of(i).data(), k, scratch);
    }
  });
  std::vector<char> off_plane(n, 0), isolated(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
    std::vector<double> residuals, spacings;
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      const std::size_t i = order[r];
      residuals.assign(1, local[i].residual);
      spacings.clear();
      for (const std::uint32_t j : table.of(i).first(k)) {
        residuals.push_back(local[j].residual);
        spacings.push_back(local[j].mean_distance);
      }
      const Local& l = local[i];
      off_plane[i] = l.off_plane > options.off_plane_rel_radius * l.radius &&
                     l.off_plane > options.off_plane_rel_noise * upper_median_in_place(residuals);
      isolated[i] = l.mean_distance > options.isolated_rel_spacing * upper_median_in_place(spacings);
    }
  });
  for (std::size_t i = 0; i < n; ++i) {
    if (off_plane[i]) {
      ++report.off_plane;
    } else if (isolated[i]) {
      ++report.isolated;
    } else {
      continue;
    }
    report.is_outlier[i] = 1;
  }
  return report;
}

}  // namespace envcrust::outliers
