// Shared helpers of the Power Crust tests: sampled builtins, grids and the crust's quality.
#pragma once

#include "envcrust/distance.h"
#include "envcrust/power_crust.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <numbers>
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

/// Topology of the crust as built: vertices are power-diagram vertices named by cell, so
/// no welding by position (samples are degenerate power vertices where several cells share a
/// position; welding them describes a different, pinched complex).
inline topology::MeshTopology crust_topology(const TriangleMesh& crust) {
  topology::TopologyOptions options;
  options.weld_identical_vertices = false;
  return topology::analyze_topology(crust, options);
}

/// Two-sided Hausdorff distance of the crust to the builtin's exact tessellation, as a
/// fraction of the tessellation's bbox diagonal.
inline double relative_hausdorff(const TriangleMesh& crust, const std::string& name) {
  const auto surface = surfaces::make_builtin(name);
  surfaces::TessellationOptions tessellation;
  tessellation.max_error_rel_diag = 1e-4;
  const TriangleMesh truth = surfaces::tessellate(*surface, tessellation);
  distance::DistanceOptions options;
  options.samples = 20000;
  const auto report = distance::compare_to_mesh(crust, truth, options);
  return report.relative(report.hausdorff);
}

/// The unit sphere on latitude/longitude rings plus both poles: many cospherical subsets.
inline std::vector<Point3> sphere_rings(int rings, int per_ring) {
  std::vector<Point3> points{Point3(0, 0, 1), Point3(0, 0, -1)};
  for (int i = 1; i < rings; ++i) {
    const double theta = std::numbers::pi * i / rings;
    for (int j = 0; j < per_ring; ++j) {
      const double phi = 2 * std::numbers::pi * j / per_ring;
      points.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  }
  return points;
}

/// The surface of the cube [-1, 1]^3 on a regular grid of n x n squares per face (exact
/// dyadic coordinates for n a power of two): exactly cospherical and coplanar subsets.
inline std::vector<Point3> cube_grid(int n) {
  std::vector<Point3> points;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        if (i != 0 && i != n && j != 0 && j != n && k != 0 && k != n) continue;
        points.emplace_back(-1 + 2.0 * i / n, -1 + 2.0 * j / n, -1 + 2.0 * k / n);
      }
  return points;
}

/// A point-in-solid test for a closed, consistently oriented crust.
class InsideTest {
 public:
  explicit InsideTest(const TriangleMesh& crust) {
    std::vector<std::vector<std::size_t>> faces;
    for (const auto& t : crust.triangles) faces.push_back({t[0], t[1], t[2]});
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(crust.vertices, faces, mesh_);
    side_ = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(mesh_);
  }
  [[nodiscard]] CGAL::Bounded_side side(const Point3& p) const { return (*side_)(p); }

 private:
  using Mesh = CGAL::Surface_mesh<Point3>;
  Mesh mesh_;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side_;
};

}  // namespace envcrust::powercrust::test_support
