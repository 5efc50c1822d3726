// Tests of the ball reader ("x y z radius [label]", as powercrust --poles writes).
#include "envcrust/io.h"
#include "io_test_support.h"

namespace envcrust::io {
namespace {

using testing::io_error_of;

class BallReader : public testing::TempDirTest {};

TEST_F(BallReader, reads_centres_radii_and_optional_labels) {
  const auto file = write("poles.txt", "# x y z radius label\n0 0 0 1.5 in\n\n1 2 3 0.25 out\n4 5 6 2\n");
  const BallSet balls = read_balls(file);
  ASSERT_EQ(balls.centres.size(), 3u);
  testing::expect_same_point(Point3(1, 2, 3), balls.centres[1]);
  EXPECT_EQ(balls.radii, (std::vector<double>{1.5, 0.25, 2}));
  EXPECT_EQ(balls.labels, (std::vector<std::string>{"in", "out", ""}));
}

TEST_F(BallReader, bad_lines_are_refused_with_file_and_line) {
  const auto few = write("a.txt", "0 0 0 1\n0 0 0\n");
  EXPECT_EQ(io_error_of([&] { read_balls(few); }), few.string() + ":2: expected x y z radius [label], got 3 values");
  const auto negative = write("b.txt", "0 0 0 -1 in\n");
  EXPECT_EQ(io_error_of([&] { read_balls(negative); }), negative.string() + ":1: radius must be finite and > 0 (got -1)");
  const auto word = write("c.txt", "0 zero 0 1\n");
  EXPECT_EQ(io_error_of([&] { read_balls(word); }), word.string() + ":1: expected a number, got 'zero'");
  const auto empty = write("d.txt", "# nothing\n");
  EXPECT_EQ(io_error_of([&] { read_balls(empty); }), empty.string() + ": no balls");
}

}  // namespace
}  // namespace envcrust::io
