// Tests of the ball reader and writer (text "x y z radius [label]" or PLY, as powercrust --poles writes).
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

TEST_F(BallReader, text_and_ply_round_trip_centres_radii_and_labels) {
  BallSet balls;
  balls.centres = {Point3(0, 0, 0), Point3(1.0 / 3, -2, 1e-7), Point3(4, 5, 6)};
  balls.radii = {1.5, 0.1, 2e3};
  balls.labels = {"in", "out", "unknown"};
  for (const char* name : {"poles.txt", "poles.ply"}) {
    const auto file = path(name);
    write_balls(file, balls);
    const BallSet back = read_balls(file);
    ASSERT_EQ(back.centres.size(), 3u) << name;
    for (std::size_t i = 0; i < 3; ++i) testing::expect_same_point(balls.centres[i], back.centres[i]);
    EXPECT_EQ(back.radii, balls.radii) << name;
    EXPECT_EQ(back.labels, balls.labels) << name;
  }
}

TEST_F(BallReader, ply_without_radius_and_unwritable_balls_are_refused) {
  const auto plain = write("p.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                    "property float z\nend_header\n0 0 0\n");
  EXPECT_EQ(io_error_of([&] { read_balls(plain); }), plain.string() + ": PLY vertices have no 'radius' property");
  BallSet balls;
  balls.centres = {Point3(0, 0, 0)};
  balls.radii = {1};
  balls.labels = {"inside"};
  const auto out = path("q.ply");
  EXPECT_EQ(io_error_of([&] { write_balls(out, balls); }),
            out.string() + ": cannot write ball label 'inside' to PLY (in, out or unknown)");
  balls.labels = {"in"};
  balls.radii = {0};
  EXPECT_EQ(io_error_of([&] { write_balls(out, balls); }), out.string() + ": radius must be finite and > 0 (got 0) at ball 0");
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace envcrust::io
