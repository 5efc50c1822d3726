// Tests of the plain-text point readers (.xyz/.pts/.txt/.csv) through read_points.
#include "envcrust/io.h"
#include "io_test_support.h"

namespace envcrust::io {
namespace {

using testing::io_error_of;

class PointReader : public testing::TempDirTest {};

TEST_F(PointReader, reads_three_columns_with_comments_and_blank_lines) {
  const auto file = write("a.xyz",
                          "# header comment\n"
                          "\n"
                          "1 2 3\n"
                          "  -4.5\t5e-3  +6  # trailing comment\n"
                          "\r\n"
                          "7 8 9\r\n");
  const PointSet points = read_points(file);
  ASSERT_EQ(points.size(), 3U);
  EXPECT_FALSE(points.has_normals());
  testing::expect_same_point(Point3(1, 2, 3), points.points[0]);
  testing::expect_same_point(Point3(-4.5, 5e-3, 6), points.points[1]);
  testing::expect_same_point(Point3(7, 8, 9), points.points[2]);
}

TEST_F(PointReader, reads_six_columns_as_points_and_normals) {
  const auto file = write("a.pts", "0 0 0 0 0 1\n1 0 0 0 1 0\n");
  const PointSet points = read_points(file);
  ASSERT_EQ(points.size(), 2U);
  ASSERT_TRUE(points.has_normals());
  EXPECT_EQ(points.normals[0], Vector3(0, 0, 1));
  EXPECT_EQ(points.normals[1], Vector3(0, 1, 0));
}

TEST_F(PointReader, accepts_txt_csv_and_upper_case_extensions) {
  EXPECT_EQ(read_points(write("a.txt", "1 2 3\n")).size(), 1U);
  EXPECT_EQ(read_points(write("c.csv", "1,2,3\n")).size(), 1U);
  EXPECT_EQ(read_points(write("b.XYZ", "1 2 3")).size(), 1U);
}

TEST_F(PointReader, reads_last_line_without_newline) {
  const PointSet points = read_points(write("a.xyz", "1 2 3\n4 5 6"));
  ASSERT_EQ(points.size(), 2U);
  testing::expect_same_point(Point3(4, 5, 6), points.points[1]);
}

TEST_F(PointReader, reads_doubles_exactly) {
  const PointSet points = read_points(write("a.xyz", "0.1 1e-300 123456789.123456789\n"));
  EXPECT_EQ(points.points[0].x(), 0.1);
  EXPECT_EQ(points.points[0].y(), 1e-300);
  EXPECT_EQ(points.points[0].z(), 123456789.123456789);
}

constexpr const char* kTooFew =
    "expected at least 3 numbers (x y z, then optional columns: nx ny nz, intensity, r g b, ...), got ";

TEST_F(PointReader, reports_line_of_too_few_columns) {
  const auto file = write("a.xyz", "# comment\n\n1 2\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ":3: " + kTooFew + "2");
}

// x y z intensity, as scanners export them: the fourth column is a scalar attribute.
TEST_F(PointReader, four_columns_are_a_position_and_an_intensity) {
  const AttributedPoints four = read_attributed_points(write("b.xyz", "1 2 3 0.5\n4 5 6 -7\n"));
  ASSERT_EQ(four.points.size(), 2U);
  EXPECT_FALSE(four.points.has_normals());
  testing::expect_same_point(Point3(4, 5, 6), four.points.points[1]);
  EXPECT_FALSE(four.attributes.has_colours());
  ASSERT_EQ(four.attributes.names, std::vector<std::string>{"intensity"});
  EXPECT_EQ(four.attributes.scalars[0], (std::vector<float>{0.5F, -7.0F}));
  EXPECT_EQ(read_points(write("c.xyz", "1 2 3 0.5\n")).size(), 1U);  // read_points drops it
}

// Column counts with no common meaning: x y z, then scalars named by their column.
TEST_F(PointReader, other_column_counts_keep_their_columns_as_scalars) {
  const AttributedPoints five = read_attributed_points(write("a.txt", "1 2 3 10 20\n"));
  EXPECT_EQ(five.attributes.names, (std::vector<std::string>{"column_4", "column_5"}));
  EXPECT_EQ(five.attributes.scalars[1], std::vector<float>{20.0F});
  // seven columns outside .pts too: x y z intensity r g b when the last three are colours
  const AttributedPoints seven = read_attributed_points(write("b.txt", "1 2 3 0.1 0.5 0.5 0.5\n"));
  EXPECT_FALSE(seven.attributes.has_colours());
  EXPECT_EQ(seven.attributes.names, (std::vector<std::string>{"intensity", "column_5", "column_6", "column_7"}));
}

// Nine columns: normals and colours, the triple of whole numbers 0..255 being the colour.
TEST_F(PointReader, nine_columns_are_normals_and_colours_in_either_order) {
  const AttributedPoints after = read_attributed_points(write("a.xyz", "1 2 3 0 0 1 255 128 0\n4 5 6 0 1 0 1 2 3\n"));
  ASSERT_TRUE(after.points.has_normals());
  EXPECT_EQ(after.points.normals[1], Vector3(0, 1, 0));
  ASSERT_TRUE(after.attributes.has_colours());
  EXPECT_EQ(after.attributes.colours[0], (Colour{255, 128, 0}));
  EXPECT_TRUE(after.attributes.names.empty());
  // CloudCompare's x y z r g b nx ny nz
  const AttributedPoints before = read_attributed_points(write("b.xyz", "1 2 3 255 128 0 0 0 1\n"));
  EXPECT_EQ(before.points.normals.at(0), Vector3(0, 0, 1));
  EXPECT_EQ(before.attributes.colours.at(0), (Colour{255, 128, 0}));
}

// Files exported as comma-separated values read the same, with or without spaces.
TEST_F(PointReader, reads_comma_separated_columns) {
  const PointSet points = read_points(write("a.xyz", "1,2,3, 0,0,1\n4, 5.5 ,6,0, 1,0\n"));
  ASSERT_EQ(points.size(), 2U);
  ASSERT_TRUE(points.has_normals());
  testing::expect_same_point(Point3(4, 5.5, 6), points.points[1]);
  EXPECT_EQ(points.normals[1], Vector3(0, 1, 0));
  const auto empty_field = write("b.xyz", "1,2,,3\n");
  EXPECT_EQ(io_error_of([&] { read_points(empty_field); }), empty_field.string() + ":1: expected a number, got ''");
  const auto missing = write("c.xyz", "1,,3\n");
  EXPECT_EQ(io_error_of([&] { read_points(missing); }), missing.string() + ":1: expected a number, got ''");
}

// A first line of names picks the columns by name, whatever else the file holds.
TEST_F(PointReader, a_header_line_names_the_columns_and_the_others_are_skipped) {
  const PointSet csv = read_points(write("a.csv",
                                         "//X,Y,Z,R,G,B,Nx,Ny,Nz,Intensity\n"
                                         "1,2,3,255,0,0,0,0,1,0.5\n"
                                         "4,5,6,0,255,0,0,1,0,0.25\n"));
  ASSERT_EQ(csv.size(), 2U);
  ASSERT_TRUE(csv.has_normals());
  testing::expect_same_point(Point3(4, 5, 6), csv.points[1]);
  EXPECT_EQ(csv.normals[0], Vector3(0, 0, 1));
  // columns in another order, quoted names, white space; intensity text is never parsed
  const PointSet reordered = read_points(write("b.txt", "\"intensity\" \"z\" \"y\" \"x\"\nhigh 3 2 1\n"));
  ASSERT_EQ(reordered.size(), 1U);
  EXPECT_FALSE(reordered.has_normals());
  testing::expect_same_point(Point3(1, 2, 3), reordered.points[0]);
  const PointSet spelled = read_points(write("c.xyz", "x y z normal_x normal_y normal_z\n0 0 0 1 0 0\n"));
  EXPECT_EQ(spelled.normals.at(0), Vector3(1, 0, 0));
  // the colour and the other numeric columns are attributes; a column of text is none
  const AttributedPoints attributed = read_attributed_points(write("f.csv",
                                                                   "X,Y,Z,Red,Green,Blue,Intensity,Class\n"
                                                                   "1,2,3,255,0,7,0.5,ground\n"
                                                                   "4,5,6,0,255,0,0.25,tree\n"));
  ASSERT_TRUE(attributed.attributes.has_colours());
  EXPECT_EQ(attributed.attributes.colours[0], (Colour{255, 0, 7}));
  EXPECT_EQ(attributed.attributes.names, std::vector<std::string>{"intensity"});
  EXPECT_EQ(attributed.attributes.scalars[0], (std::vector<float>{0.5F, 0.25F}));
  // colours written as fractions of 1
  const AttributedPoints fractions = read_attributed_points(write("g.csv", "x,y,z,r,g,b\n1,2,3,1,0.5,0\n"));
  EXPECT_EQ(fractions.attributes.colours.at(0), (Colour{255, 128, 0}));
  EXPECT_EQ(io_error_of([&] { read_points(write("h.csv", "x,y,z,r,g,b\n1,2,3,red,0,0\n")); }),
            path("h.csv").string() + ":2: expected a number, got 'red'");
  // a spreadsheet's export starts with a UTF-8 byte-order mark
  EXPECT_EQ(read_points(write("d.csv", "\xEF\xBB\xBFX,Y,Z\n1,2,3\n")).size(), 1U);
  EXPECT_EQ(read_points(write("e.csv", "\xEF\xBB\xBF" "1,2,3\n")).size(), 1U);
}

TEST_F(PointReader, a_header_without_x_y_z_or_with_part_of_a_normal_is_refused) {
  const auto no_z = write("a.csv", "# export\nx,y,intensity\n1,2,3\n");
  EXPECT_EQ(io_error_of([&] { read_points(no_z); }),
            no_z.string() + ":2: a header line must name the x, y and z columns (and may name nx, ny, nz), got "
                            "'x', 'y', 'intensity'");
  const auto part = write("b.csv", "x,y,z,nx,ny\n1,2,3,0,1\n");
  EXPECT_EQ(io_error_of([&] { read_points(part); }),
            part.string() + ":1: the header names some normal columns but not all three (nx, ny, nz), got "
                            "'x', 'y', 'z', 'nx', 'ny'");
  const auto short_line = write("c.csv", "x,y,z,i\n1,2,3,4\n1,2,3\n");
  EXPECT_EQ(io_error_of([&] { read_points(short_line); }),
            short_line.string() + ":3: expected 4 fields (as the header on line 1 names), got 3");
  const auto bad = write("d.csv", "x,y,z\n1,2,three\n");
  EXPECT_EQ(io_error_of([&] { read_points(bad); }), bad.string() + ":2: expected a number, got 'three'");
  const auto only_header = write("e.csv", "x,y,z\n");
  EXPECT_EQ(io_error_of([&] { read_points(only_header); }), only_header.string() + ": no points");
}

// Leica's .pts: a point count before each scan, then x y z intensity [r g b].
TEST_F(PointReader, pts_files_skip_point_counts_and_read_intensity_and_colours) {
  const AttributedPoints seven =
      read_attributed_points(write("a.pts", "2\n1 2 3 -120 10 20 30\n4 5 6 -80 40 50 60\n1\n7 8 9 0 0 0 0\n"));
  ASSERT_EQ(seven.points.size(), 3U);
  EXPECT_FALSE(seven.points.has_normals());
  testing::expect_same_point(Point3(7, 8, 9), seven.points.points[2]);
  EXPECT_EQ(seven.attributes.names, std::vector<std::string>{"intensity"});
  EXPECT_EQ(seven.attributes.scalars[0], (std::vector<float>{-120.0F, -80.0F, 0.0F}));
  ASSERT_TRUE(seven.attributes.has_colours());
  EXPECT_EQ(seven.attributes.colours[1], (Colour{40, 50, 60}));
  const PointSet four = read_points(write("b.pts", "1\n1 2 3 0.5\n"));
  ASSERT_EQ(four.size(), 1U);
  testing::expect_same_point(Point3(1, 2, 3), four.points[0]);
  // elsewhere a lone number is no count
  const auto xyz = write("c.xyz", "2\n1 2 3\n");
  EXPECT_EQ(io_error_of([&] { read_points(xyz); }), xyz.string() + ":1: " + kTooFew + "1");
}

TEST_F(PointReader, reports_inconsistent_column_count) {
  const auto file = write("a.xyz", "1 2 3\n4 5 6\n\n7 8 9 0 0 1\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ":4: expected 3 numbers (as on line 1), got 6");
}

TEST_F(PointReader, reports_text_that_is_not_a_number) {
  const auto file = write("a.xyz", "1 2 3\n4 five 6\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ":2: expected a number, got 'five'");
}

TEST_F(PointReader, reports_nan_coordinate) {
  const auto file = write("a.xyz", "1 2 3\n4 nan 6\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ":2: non-finite coordinate");
}

TEST_F(PointReader, reports_infinite_coordinate) {
  const auto file = write("a.xyz", "1 2 3\n\n-inf 5 6\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ":3: non-finite coordinate");
}

TEST_F(PointReader, a_number_beyond_double_range_is_non_finite_and_one_below_it_is_zero) {
  const auto huge = write("h.xyz", "1 2 3\n4 1e999 6\n");
  EXPECT_EQ(io_error_of([&] { read_points(huge); }), huge.string() + ":2: non-finite coordinate");
  const auto tiny = write("t.xyz", "1e-999 2 3\n");
  EXPECT_EQ(read_points(tiny).points.at(0).x(), 0.0);
}

TEST_F(PointReader, refuses_a_finite_coordinate_too_large_to_compute_with) {
  // 1e308 is a double, but its square is not: areas and distances would overflow.
  const auto file = write("big.xyz", "1 2 3\n4 1e308 6\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ":2: coordinate beyond 1e30 in magnitude: scale the input down");
  EXPECT_EQ(read_points(write("ok.xyz", "1e30 -1e30 3\n")).points.at(0).x(), 1e30);
}

TEST_F(PointReader, reports_nan_normal) {
  const auto file = write("a.xyz", "1 2 3 0 0 nan\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ":1: non-finite normal");
}

TEST_F(PointReader, reports_empty_file_as_no_points) {
  const auto file = write("a.xyz", "");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ": no points");
}

TEST_F(PointReader, reports_comment_only_file_as_no_points) {
  const auto file = write("a.xyz", "# nothing\n\n   \n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ": no points");
}

}  // namespace
}  // namespace envcrust::io
