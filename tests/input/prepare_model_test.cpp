// Tests of input::prepare_model: a built-in surface's samples come with its exact normals and
// boundary curves, and stay built-in (no scan settings).
#include "envcrust/input.h"
#include "envcrust/models.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace envcrust {
namespace {

models::PatchModel builtin_model(const std::string& name) {
  std::vector<std::unique_ptr<surfaces::Surface>> one;
  one.push_back(surfaces::make_builtin(name));
  return models::PatchModel(std::move(one), name);
}

TEST(PrepareModel, hemisphere_samples_have_exact_normals_and_one_boundary_curve) {
  surfaces::SampleOptions sampling;
  sampling.count = 1000;
  sampling.seed = 4;
  const auto prepared = input::prepare_model(builtin_model("hemisphere"), sampling);
  ASSERT_EQ(prepared.samples.points.size(), 1000u);
  ASSERT_EQ(prepared.samples.normals.size(), 1000u);
  for (std::size_t i = 0; i < 1000; ++i) {
    const Vector3 radial = prepared.samples.points[i] - CGAL::ORIGIN;
    // The unit hemisphere's normal at p is p itself (up to sign).
    EXPECT_NEAR(std::abs(prepared.samples.normals[i] * radial), 1.0, 1e-9) << i;
  }
  EXPECT_EQ(prepared.samples.boundary.size(), 1u);
  EXPECT_TRUE(prepared.kind.is_builtin);
  EXPECT_FALSE(prepared.kind.are_normals_estimated);
  ASSERT_EQ(prepared.notes.size(), 1u);
  EXPECT_EQ(prepared.notes.front(), "exact normals and boundary curves of hemisphere");
}

TEST(PrepareModel, the_same_seed_gives_the_same_samples) {
  surfaces::SampleOptions sampling;
  sampling.count = 300;
  const auto model = builtin_model("square");
  EXPECT_EQ(input::prepare_model(model, sampling).samples.points, input::prepare_model(model, sampling).samples.points);
}

}  // namespace
}  // namespace envcrust
