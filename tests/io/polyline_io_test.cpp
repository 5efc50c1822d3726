// Tests of polyline reading (both layouts) and writing.
#include "envcrust/io.h"
#include "io_test_support.h"

namespace envcrust::io {
namespace {

using testing::io_error_of;

class PolylineIo : public testing::TempDirTest {};

const Polyline triangle = {Point3(0.1, 0, 0), Point3(1, 0, 1.0 / 3.0), Point3(0, 1, -2e-300)};

void expect_same_curve(const Polyline& expected, const Polyline& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    testing::expect_same_point(expected[i], actual[i]);
  }
}

TEST_F(PolylineIo, round_trips_exactly_as_polyline_and_xyz) {
  for (const char* name : {"c.polyline", "c.xyz"}) {
    const auto file = path(name);
    write_polyline(file, triangle);
    expect_same_curve(triangle, read_polyline(file));
  }
}

TEST_F(PolylineIo, reads_cgal_single_line_format_and_drops_repeated_first_point) {
  const auto file = write("c.polyline", "# CGAL\n4 0 0 0 1 0 0 0 1 0 0 0 0\n");
  expect_same_curve({Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)}, read_polyline(file));
}

TEST_F(PolylineIo, reads_one_point_per_line_and_drops_repeated_first_point) {
  const auto file = write("c.polyline", "0 0 0\n1 0 0\n\n0 1 0\n0 0 0\n");
  expect_same_curve({Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)}, read_polyline(file));
}

TEST_F(PolylineIo, reads_a_csv_curve_with_a_header_line) {
  const auto file = write("c.csv", "x,y,z,t\n0,0,0,0.0\n1,0,0,0.3\n0,1,0,0.6\n");
  expect_same_curve({Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)}, read_polyline(file));
}

TEST_F(PolylineIo, refuses_second_polyline_in_cgal_format) {
  const auto file = write("c.polyline", "3 0 0 0 1 0 0 0 1 0\n3 0 0 0 1 0 0 0 1 0\n");
  EXPECT_EQ(io_error_of([&] { read_polyline(file); }),
            file.string() + ":2: expected one polyline, found another after line 1");
}

TEST_F(PolylineIo, reports_line_with_wrong_number_count) {
  const auto file = write("c.polyline", "0 0 0\n1 0 0\n0 1\n");
  EXPECT_EQ(io_error_of([&] { read_polyline(file); }),
            file.string() + ":3: expected 3 numbers, got 2");
}

TEST_F(PolylineIo, reports_too_few_points) {
  const auto file = write("c.polyline", "0 0 0\n1 0 0\n0 0 0\n");
  EXPECT_EQ(io_error_of([&] { read_polyline(file); }),
            file.string() + ": polyline has 2 points (need at least 3)");
}

TEST_F(PolylineIo, repeated_points_count_once) {
  const auto twice = write("c.xyz", "0 0 0\n1 0 0\n1 0 0\n0 1 0\n0 1 0\n0 0 0\n");
  EXPECT_EQ(read_polyline(twice).size(), 3u);
  const auto one = write("d.xyz", "1 2 3\n1 2 3\n1 2 3\n1 2 3\n");
  EXPECT_EQ(io_error_of([&] { read_polyline(one); }), one.string() + ": polyline has 1 distinct points (need at least 3)");
}

TEST_F(PolylineIo, reports_non_finite_coordinate) {
  const auto file = write("c.polyline", "0 0 0\n1 0 inf\n0 1 0\n");
  EXPECT_EQ(io_error_of([&] { read_polyline(file); }), file.string() + ":2: non-finite coordinate");
}

TEST_F(PolylineIo, reports_unknown_extension) {
  const auto file = write("c.ply", "ply\n");
  EXPECT_EQ(io_error_of([&] { read_polyline(file); }),
            file.string() + ": unknown extension '.ply' (expected .polyline, .xyz, .txt, .pts, .csv)");
}

}  // namespace
}  // namespace envcrust::io
