// reconstruct's last step for scans: the samples meshed along the sheet, kept only when their
// mesh has the sheet's topology.
#include "fixtures/surface_samples.h"

#include "envcrust/pipeline.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace envcrust {
namespace {

pipeline::ReconstructOptions with_sample_meshing() {
  pipeline::ReconstructOptions options;
  options.mesh_samples = interpolate::InterpolateOptions{};
  return options;
}

TEST(SampleMeshing, hemisphere_comes_out_on_its_own_samples) {
  const auto samples = fixtures::builtin_samples("hemisphere", 3000);
  const auto result = pipeline::reconstruct(samples, with_sample_meshing());
  ASSERT_TRUE(result.sample_meshing.has_value());
  EXPECT_TRUE(result.sample_meshing->is_kept) << result.sample_meshing->samples_topology;
  EXPECT_EQ(result.sample_meshing->samples_topology, "chi 1, 1 loop, 1 piece, orientable");
  EXPECT_LE(result.mesh.vertices.size(), samples.points.size());
  EXPECT_GE(result.mesh.vertices.size(), samples.points.size() - 10);
  std::vector<Point3> sorted = samples.points;
  std::sort(sorted.begin(), sorted.end());
  for (const Point3& v : result.mesh.vertices) ASSERT_TRUE(std::binary_search(sorted.begin(), sorted.end(), v));
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
}

TEST(SampleMeshing, moebius_strip_keeps_its_non_orientable_sheet) {
  const auto samples = fixtures::builtin_samples("moebius", 3000);
  const auto result = pipeline::reconstruct(samples, with_sample_meshing());
  ASSERT_TRUE(result.sample_meshing.has_value());
  EXPECT_FALSE(result.sample_meshing->is_kept);
  EXPECT_EQ(result.sample_meshing->sheet_topology, "chi 0, 1 loop, 1 piece, non-orientable");
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_FALSE(t.is_orientable);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_GT(result.mesh.vertices.size(), samples.points.size());  // the sheet's own vertices
}

TEST(SampleMeshing, is_the_default_for_files_and_gives_way_to_remeshing) {
  pipeline::InputKind scan;
  scan.is_builtin = false;
  scan.are_normals_estimated = true;
  EXPECT_TRUE(pipeline::options_for_input(scan).mesh_samples.has_value());  // a file: its own samples
  EXPECT_FALSE(pipeline::options_for_input({}).mesh_samples.has_value());   // a built-in: its sheet
  auto options = with_sample_meshing();
  options.remesh = remesh::RemeshOptions{};
  const auto result = pipeline::reconstruct(fixtures::builtin_samples("hemisphere", 2000), options);
  EXPECT_FALSE(result.sample_meshing.has_value());
  EXPECT_TRUE(result.remesh_stats.has_value());
}

}  // namespace
}  // namespace envcrust
