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

// An advancing front cannot make a Moebius band: the sheet stays, simplified to about as many
// vertices as there are samples (as extracted it has several times as many).
TEST(SampleMeshing, moebius_strip_keeps_its_non_orientable_sheet_at_the_samples_resolution) {
  const auto samples = fixtures::builtin_samples("moebius", 3000);
  const auto result = pipeline::reconstruct(samples, with_sample_meshing());
  ASSERT_TRUE(result.sample_meshing.has_value());
  EXPECT_FALSE(result.sample_meshing->is_kept);
  EXPECT_EQ(result.sample_meshing->sheet_topology, "chi 0, 1 loop, 1 piece, non-orientable");
  // Not even tried: the front's faces are wound from their neighbours', always orientable.
  EXPECT_EQ(result.sample_meshing->samples_topology, "no mesh (an advancing front makes only orientable surfaces)");
  EXPECT_EQ(result.sample_meshing->stats.seconds, 0.0);
  ASSERT_TRUE(result.simplify_stats.has_value());
  EXPECT_TRUE(result.simplify_stats->is_simplified) << (result.warnings.empty() ? "" : result.warnings.back());
  EXPECT_GT(result.simplify_stats->vertices_before, 3 * samples.points.size());
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_FALSE(t.is_orientable);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_GT(2 * result.mesh.vertices.size(), samples.points.size());
  EXPECT_LT(result.mesh.vertices.size(), 2 * samples.points.size());
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
