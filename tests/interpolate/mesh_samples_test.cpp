// mesh_samples: the samples meshed along a sheet that says where the surface is.
#include "envcrust/interpolate.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace envcrust {
namespace {

std::vector<Point3> builtin_points(const std::string& name, std::size_t count) {
  surfaces::SampleOptions options;
  options.count = count;
  return surfaces::sample_surface(*surfaces::make_builtin(name), options).points;
}

TriangleMesh builtin_sheet(const std::string& name) {
  return surfaces::tessellate(*surfaces::make_builtin(name));
}

// A flat grid over [-1, 1]^2 in the plane z = 0, keeping the cells whose centre `keep` says.
template <typename Keep>
TriangleMesh plane_grid(int n, Keep keep) {
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0);
  auto at = [n](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (!keep(-1.0 + 2.0 * (i + 0.5) / n, -1.0 + 2.0 * (j + 0.5) / n)) continue;
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

// Points uniform on the disc of radius 1 in z = 0, except within `hole` of the centre.
std::vector<Point3> disc_points(std::size_t count, double hole) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point3> out;
  while (out.size() < count) {
    const double x = u(random), y = u(random), r = std::hypot(x, y);
    if (r <= 1.0 && r >= hole) out.emplace_back(x, y, 0.0);
  }
  return out;
}

TEST(MeshSamples, hemisphere_is_a_disc_on_its_own_samples) {
  const auto points = builtin_points("hemisphere", 4000);
  const auto result = interpolate::mesh_samples(points, builtin_sheet("hemisphere"));
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.duplicate_faces, 0u);
  // Every vertex is the sample it names, and nearly all samples are used.
  ASSERT_EQ(result.sample_of.size(), result.mesh.vertices.size());
  for (std::size_t v = 0; v < result.mesh.vertices.size(); ++v)
    ASSERT_EQ(result.mesh.vertices[v], points[result.sample_of[v]]);
  EXPECT_GE(result.mesh.vertices.size(), 3990u);
  EXPECT_GT(result.stats.spacing, 0.0);
}

TEST(MeshSamples, the_sheet_opens_a_hole_the_samples_do_not_show) {
  // Samples fill the whole disc; the sheet has a square hole of half-width 0.3 in its middle.
  const auto points = disc_points(6000, 0.0);
  const auto full = plane_grid(80, [](double x, double y) { return std::hypot(x, y) < 1.05; });
  const auto holed = plane_grid(80, [](double x, double y) {
    return std::hypot(x, y) < 1.05 && (std::abs(x) > 0.3 || std::abs(y) > 0.3);
  });
  const auto whole = topology::analyze_topology(interpolate::mesh_samples(points, full).mesh);
  EXPECT_EQ(whole.boundary_loops.size(), 1u);
  EXPECT_EQ(whole.euler_characteristic, 1);
  const auto result = interpolate::mesh_samples(points, holed);
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.boundary_loops.size(), 2u);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_GT(result.stats.candidates_refused, 0u);
  // No face reaches into the hole further than a sample spacing or so.
  for (const auto& f : result.mesh.triangles) {
    const Point3 c = CGAL::centroid(result.mesh.vertices[f[0]], result.mesh.vertices[f[1]], result.mesh.vertices[f[2]]);
    ASSERT_FALSE(std::abs(c.x()) < 0.25 && std::abs(c.y()) < 0.25) << c;
  }
}

TEST(MeshSamples, a_gap_in_the_samples_where_the_sheet_goes_on_is_closed) {
  // No samples within 0.06 of the centre (about 2.5 spacings across); the sheet is whole.
  const auto points = disc_points(6000, 0.06);
  const auto sheet = plane_grid(80, [](double x, double y) { return std::hypot(x, y) < 1.05; });
  const auto result = interpolate::mesh_samples(points, sheet);
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.misoriented_edges, 0u);
}

TEST(MeshSamples, too_few_samples_or_no_sheet_give_nothing) {
  const auto sheet = builtin_sheet("hemisphere");
  EXPECT_TRUE(interpolate::mesh_samples({Point3(0, 0, 1), Point3(0.1, 0, 1)}, sheet).mesh.triangles.empty());
  EXPECT_TRUE(interpolate::mesh_samples(builtin_points("hemisphere", 500), TriangleMesh{}).mesh.triangles.empty());
}

}  // namespace
}  // namespace envcrust
