// Tests of input::prepare_points: duplicates merged with their attributes, a stray point
// removed, normal lines fitted (and turned like given ones across creases), the hemisphere's
// rim detected or given as one loop, colour columns read as colours, and the exact refusals.
#include "fixtures/shapes.h"
#include "fixtures/surface_samples.h"

#include "envcrust/errors.h"
#include "envcrust/input.h"
#include "input/expect_refusal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace envcrust {
namespace {

// `count` samples of the built-in hemisphere (unit radius, rim circle at z = 0), seed 1.
PointSet hemisphere(std::size_t count, bool with_normals = false) {
  const auto samples = fixtures::builtin_samples("hemisphere", count);
  PointSet out;
  out.points = samples.points;
  if (with_normals) out.normals = samples.normals;
  return out;
}

input::PointInput as_input(PointSet points) {
  input::PointInput in;
  in.points.points = std::move(points);
  return in;
}

bool has_note(const input::PreparedInput& prepared, const std::string& note) {
  for (const auto& n : prepared.notes)
    if (n == note) return true;
  return false;
}

TEST(PreparePoints, hemisphere_without_normals_gets_unit_normal_lines_and_one_detected_rim) {
  const auto prepared = input::prepare_points(as_input(hemisphere(2000)));
  ASSERT_EQ(prepared.samples.points.size(), 2000u);
  ASSERT_EQ(prepared.samples.normals.size(), 2000u);
  EXPECT_TRUE(prepared.kind.are_normals_estimated);
  EXPECT_FALSE(prepared.kind.is_builtin);
  EXPECT_TRUE(has_note(prepared, "normal lines estimated by PCA over 24 neighbours"));
  // The exact normal line of the unit hemisphere at p is along p: PCA over 24 neighbours of
  // 2,000 clean samples is within 10 degrees of it at all but a few rim samples.
  std::size_t off_by_10_deg = 0;
  for (std::size_t i = 0; i < prepared.samples.points.size(); ++i) {
    const Vector3 n = prepared.samples.normals[i];
    EXPECT_NEAR(n.squared_length(), 1.0, 1e-9);
    const Vector3 radial = prepared.samples.points[i] - CGAL::ORIGIN;
    const double cos_angle = std::abs(n * radial) / std::sqrt(radial.squared_length());
    off_by_10_deg += cos_angle < std::cos(10.0 * M_PI / 180.0);
  }
  EXPECT_LE(off_by_10_deg, 20u);
  EXPECT_EQ(prepared.samples.boundary.size(), 1u);
  EXPECT_TRUE(prepared.kind.is_boundary_detected);
  ASSERT_TRUE(prepared.detection.has_value());
  EXPECT_TRUE(prepared.detection->curves.empty());  // moved into samples.boundary
  EXPECT_TRUE(prepared.outliers.empty());
}

TEST(PreparePoints, no_boundary_detection_reads_the_points_as_a_closed_surface) {
  input::InputOptions options;
  options.use_boundary_detection = false;
  const auto prepared = input::prepare_points(as_input(hemisphere(1000)), options);
  EXPECT_TRUE(prepared.samples.boundary.empty());
  EXPECT_FALSE(prepared.kind.is_boundary_detected);
  EXPECT_FALSE(prepared.detection.has_value());
}

TEST(PreparePoints, given_rim_points_make_one_boundary_curve_named_in_the_note) {
  input::PointInput in = as_input(hemisphere(2000));
  input::GivenBoundary rim;
  for (int i = 0; i < 60; ++i)
    rim.points.points.emplace_back(std::cos(2 * M_PI * i / 60), std::sin(2 * M_PI * i / 60), 0.0);
  rim.name = "rim.xyz";
  in.given_boundary = rim;
  const auto prepared = input::prepare_points(std::move(in));
  EXPECT_EQ(prepared.samples.boundary.size(), 1u);
  EXPECT_FALSE(prepared.kind.is_boundary_detected);
  EXPECT_TRUE(has_note(prepared, "boundary given: 1 curves from 60 points of rim.xyz"));
}

TEST(PreparePoints, an_empty_given_boundary_is_refused_naming_its_files) {
  input::PointInput in = as_input(hemisphere(500));
  in.given_boundary = input::GivenBoundary{{}, "a.xyz, b.polyline"};
  input::InputOptions options;
  options.name = "scan.xyz";
  expect_refusal<InvalidInput>([&] { input::prepare_points(std::move(in), options); },
                  "a.xyz, b.polyline: no boundary points given");
}

// 20 points repeated, each copy with another colour: merged, each keeping its first
// occurrence's colour, and the attributes stay one per sample kept.
TEST(PreparePoints, duplicates_are_merged_keeping_the_first_occurrences_attributes) {
  input::PointInput in = as_input(hemisphere(500));
  auto& points = in.points.points.points;
  for (std::size_t i = 0; i < 500; ++i)
    in.points.attributes.colours.push_back({static_cast<std::uint8_t>(i % 256), static_cast<std::uint8_t>(i / 256), 7});
  for (std::size_t i = 0; i < 20; ++i) {
    points.push_back(points[i]);
    in.points.attributes.colours.push_back({0, 0, 255});
  }
  const auto prepared = input::prepare_points(std::move(in));
  EXPECT_TRUE(has_note(prepared, "20 duplicate points merged"));
  ASSERT_EQ(prepared.samples.points.size(), 500u);
  ASSERT_EQ(prepared.attribute_points.size(), 500u);
  ASSERT_EQ(prepared.attributes.colours.size(), 500u);
  const auto original = hemisphere(500).points;
  for (std::size_t i = 0; i < 500; ++i) {
    ASSERT_EQ(prepared.attribute_points[i], original[i]) << i;
    EXPECT_EQ(prepared.attributes.colours[i][0], i % 256) << i;
    EXPECT_EQ(prepared.attributes.colours[i][2], 7) << i;
  }
}

// A point 2 radii above the pole, far from every sample: removed with its colour (flagged by
// the plane test, which runs first: it lies far off the plane of its 16 nearest samples).
TEST(PreparePoints, a_stray_point_is_removed_unless_outliers_are_kept) {
  input::PointInput in = as_input(hemisphere(2000));
  in.points.points.points.emplace_back(0.0, 0.0, 3.0);
  in.points.attributes.colours.assign(2001, {1, 2, 3});
  in.points.attributes.colours.back() = {255, 0, 0};
  const auto prepared = input::prepare_points(in);
  ASSERT_EQ(prepared.outliers.size(), 1u);
  EXPECT_EQ(prepared.outliers.front(), Point3(0.0, 0.0, 3.0));
  EXPECT_TRUE(has_note(prepared, "1 outliers removed (1 off their neighbours' plane, 0 isolated)"));
  EXPECT_EQ(prepared.samples.points.size(), 2000u);
  ASSERT_EQ(prepared.attributes.colours.size(), 2000u);
  for (const auto& c : prepared.attributes.colours) EXPECT_EQ(c[0], 1);

  input::InputOptions keep;
  keep.use_outlier_removal = false;
  const auto kept = input::prepare_points(in, keep);
  EXPECT_TRUE(kept.outliers.empty());
  EXPECT_EQ(kept.samples.points.size(), 2001u);
}

// The open box's exact normals jump by 90 degrees along its edges (6.5 units long, far above a
// tenth of the diagonal): rounded off, fitted normal lines replace them, each turned to agree
// with the given normal; joined, the given normals stay and the creases go with the samples.
TEST(PreparePoints, normals_that_jump_across_creases_are_refitted_and_turned_like_the_given_ones) {
  const PointSet box = fixtures::open_box_samples(4000, 3);
  input::PointInput in = as_input(box);
  const auto rounded = input::prepare_points(in);
  EXPECT_TRUE(rounded.kind.are_normals_estimated);
  EXPECT_TRUE(rounded.kind.are_signs_given);
  EXPECT_TRUE(rounded.samples.creases.empty());
  ASSERT_EQ(rounded.samples.normals.size(), box.points.size());
  for (std::size_t i = 0; i < box.points.size(); ++i) EXPECT_GT(rounded.samples.normals[i] * box.normals[i], 0.0) << i;

  input::InputOptions join;
  join.creases = input::CreaseMode::Join;
  const auto joined = input::prepare_points(in, join);
  EXPECT_FALSE(joined.kind.are_normals_estimated);
  EXPECT_FALSE(joined.samples.creases.empty());
  for (std::size_t i = 0; i < box.points.size(); ++i) EXPECT_EQ(joined.samples.normals[i], box.normals[i]) << i;
}

// x y z r g b read as x y z nx ny nz: colours when the caller says they are text columns.
TEST(PreparePoints, whole_numbers_up_to_255_in_text_columns_are_read_as_colours) {
  input::PointInput in = as_input(hemisphere(500));
  in.points.points.normals.assign(500, Vector3(200, 10, 0));
  in.are_normals_text_columns = true;
  const auto prepared = input::prepare_points(in);
  EXPECT_TRUE(prepared.kind.are_normals_estimated);
  ASSERT_EQ(prepared.attributes.colours.size(), 500u);
  EXPECT_EQ(prepared.attributes.colours.front()[0], 200);
  EXPECT_TRUE(
      has_note(prepared, "columns 4-6 are whole numbers in 0..255 on every line: read as colours, not normals"));

  in.are_normals_text_columns = false;  // a PLY's normals: read as normals, scaled to unit length
  const auto as_normals = input::prepare_points(in);
  EXPECT_TRUE(as_normals.attributes.empty());
  EXPECT_NEAR(as_normals.samples.normals.front().squared_length(), 1.0, 1e-12);
}

TEST(PreparePoints, no_points_are_refused_with_the_count) {
  expect_refusal<DegenerateInput>([&] { input::prepare_points({}); },
                  "need at least 5 distinct points, got 0");
}

TEST(PreparePoints, refusals_start_with_the_inputs_name) {
  input::InputOptions options;
  options.name = "scan.xyz";
  PointSet few;
  for (int i = 0; i < 8; ++i) few.points.emplace_back(i % 2, i / 4, 0.0);  // 4 distinct corners, twice
  expect_refusal<DegenerateInput>([&] { input::prepare_points(as_input(few), options); },
                  "scan.xyz: need at least 5 distinct points, got 4 (4 duplicates merged)");
  PointSet zero_normal = hemisphere(10, true);
  zero_normal.normals[6] = Vector3(0, 0, 0);
  expect_refusal<InvalidInput>([&] { input::prepare_points(as_input(zero_normal), options); },
                  "scan.xyz: point 7 has a zero normal");
  PointSet line;
  for (int i = 0; i < 100; ++i) line.points.emplace_back(0.2 * i, 0.1 * i, 0.0);
  expect_refusal<DegenerateInput>([&] { input::prepare_points(as_input(line), options); },
                  "scan.xyz: all 100 points lie on a line (within 1e-5 of their extent, 22.1): no surface "
                  "to reconstruct");
}

}  // namespace
}  // namespace envcrust
