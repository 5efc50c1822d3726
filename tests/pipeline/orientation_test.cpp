// reconstruct turns its medial sheet to face like the input's oriented normals.
#include "fixtures/surface_samples.h"

#include "envcrust/pipeline.h"

#include <gtest/gtest.h>

namespace envcrust {
namespace {

// Area fraction of the faces whose normal points away from the origin.
double outward_fraction(const TriangleMesh& mesh) {
  double out = 0, all = 0;
  for (const auto& t : mesh.triangles) {
    const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Vector3 n = CGAL::cross_product(b - a, c - a);
    const double area = std::sqrt(n.squared_length());
    all += area;
    if (n * (CGAL::centroid(a, b, c) - CGAL::ORIGIN) > 0) out += area;
  }
  return out / all;
}

TEST(ResultOrientation, hemisphere_faces_like_its_outward_normals_and_turns_with_them) {
  auto samples = fixtures::builtin_samples("hemisphere", 3000);
  const auto result = pipeline::reconstruct(samples);
  ASSERT_FALSE(result.mesh.triangles.empty());
  EXPECT_GT(outward_fraction(result.mesh), 0.999);
  for (auto& n : samples.normals) n = -n;  // the same lines, the other sign
  const auto inward = pipeline::reconstruct(samples);
  EXPECT_LT(outward_fraction(inward.mesh), 0.001);
}

// Normal lines without a sign (estimated ones) do not turn the result: it faces out of the
// volume its border loop closes (the dome's outside), whichever signs the lines came with.
TEST(ResultOrientation, faces_out_of_the_volume_its_borders_close_for_estimated_normal_lines) {
  pipeline::InputKind kind;
  kind.are_normals_estimated = true;
  const auto options = pipeline::options_for_input(kind);
  EXPECT_FALSE(options.use_normal_orientation);
  EXPECT_TRUE(pipeline::options_for_input({}).use_normal_orientation);
  auto samples = fixtures::builtin_samples("hemisphere", 3000);
  for (std::size_t i = 0; i < samples.normals.size(); i += 2) samples.normals[i] = -samples.normals[i];
  EXPECT_GT(outward_fraction(pipeline::reconstruct(samples, options).mesh), 0.999);
  for (auto& n : samples.normals) n = -n;
  EXPECT_GT(outward_fraction(pipeline::reconstruct(samples, options).mesh), 0.999);
}

}  // namespace
}  // namespace envcrust
