// Tests of InputOptions::classes: the points of the classes asked for kept with their
// attributes, and the exact refusals of a choice that leaves none or has nothing to choose by.
#include "fixtures/surface_samples.h"

#include "envcrust/errors.h"
#include "envcrust/input.h"
#include "input/expect_refusal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace envcrust {
namespace {

// The built-in hemisphere's 1,500 samples, class 2 (ground), then 300 samples of the square
// 5 above it, class 6 (building), each with an intensity of its index.
input::PointInput ground_and_roof() {
  input::PointInput in;
  auto& points = in.points.points.points;
  std::vector<float> classes, intensity;
  for (const Point3& p : fixtures::builtin_samples("hemisphere", 1500).points) points.push_back(p), classes.push_back(2);
  for (const Point3& p : fixtures::builtin_samples("square", 300).points)
    points.push_back(p + Vector3(0, 0, 5)), classes.push_back(6);
  for (std::size_t i = 0; i < points.size(); ++i) intensity.push_back(static_cast<float>(i));
  in.points.attributes.names = {"intensity", "classification"};
  in.points.attributes.scalars = {intensity, classes};
  return in;
}

TEST(PointClasses, only_the_points_of_the_classes_asked_for_are_kept_with_their_attributes) {
  input::InputOptions options;
  options.classes = {2};
  const auto prepared = input::prepare_points(ground_and_roof(), options);
  EXPECT_EQ(prepared.samples.points.size(), 1500u);
  EXPECT_EQ(prepared.notes.front(), "kept the 1500 of 1800 points of class 2");
  for (const Point3& p : prepared.samples.points) EXPECT_LE(p.z(), 1.0 + 1e-12);
  ASSERT_EQ(prepared.attributes.scalars.size(), 2u);
  const auto& intensity = prepared.attributes.scalars[0];
  EXPECT_EQ(*std::max_element(intensity.begin(), intensity.end()), 1499.0f);
  EXPECT_EQ(prepared.samples.boundary.size(), 1u);  // the hemisphere's rim alone
  options.classes = {6, 2};
  EXPECT_EQ(input::prepare_points(ground_and_roof(), options).notes.front(),
            "kept the 1800 of 1800 points of class 6 or 2");
}

TEST(PointClasses, a_choice_that_leaves_no_point_is_refused_naming_the_classes_present) {
  input::InputOptions options;
  options.name = "tile.las";
  options.classes = {7, 9};
  expect_refusal<InvalidInput>([&] { input::prepare_points(ground_and_roof(), options); },
                               "tile.las: no point is of class 7 or 9 (the points' classes: 2 (1500 points), "
                               "6 (300 points))");
}

TEST(PointClasses, points_without_classification_are_refused_when_classes_are_asked_for) {
  input::PointInput in = ground_and_roof();
  in.points.attributes = {};
  input::InputOptions options;
  options.name = "scan.xyz";
  options.classes = {2, 6};
  expect_refusal<InvalidInput>([&] { input::prepare_points(in, options); },
                               "scan.xyz: the points have no classification to choose classes 2, 6 from (LAS files "
                               "have one, point files a column named 'classification')");
}

}  // namespace
}  // namespace envcrust
