// The LAS reader: versions 1.0-1.4, point data formats 0-10, scale and offset, colours,
// intensity and classification, and one-line refusals of broken and compressed files.
#include "envcrust/io.h"
#include "fixtures/las_writer.h"
#include "io_test_support.h"

#include <algorithm>
#include <string>
#include <vector>

namespace envcrust::io {
namespace {

namespace fixtures = envcrust::testing;
using fixtures::LasLayout;
using fixtures::LasPoint;

class LasReader : public testing::TempDirTest {
 protected:
  std::filesystem::path write_las(const std::string& name, const std::vector<LasPoint>& points,
                                  const LasLayout& layout = {}) {
    return write(name, fixtures::las_bytes(points, layout));
  }
  // The message reading `file` fails with, the file's name cut off.
  std::string problem(const std::filesystem::path& file) {
    const std::string message = testing::io_error_of([&] { read_attributed_points(file); });
    const std::string head = file.string() + ": ";
    if (message.rfind(head, 0) != 0) return "not naming the file: " + message;
    return message.substr(head.size());
  }
};

// Three points at coordinates that are multiples of the scale, so that they read back exactly
// up to the double arithmetic of scale times integer plus offset.
std::vector<LasPoint> three_points() {
  return {{1.25, -2.5, 0.125, 100, 2, {255, 0, 10}},
          {3.0, 4.5, -1.0, 65535, 6, {0, 128, 255}},
          {-7.75, 0.0, 2.25, 0, 1, {17, 34, 51}}};
}

std::vector<float> scalar(const AttributedPoints& read, const std::string& name) {
  const auto& names = read.attributes.names;
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return {};
  return read.attributes.scalars[static_cast<std::size_t>(it - names.begin())];
}

TEST_F(LasReader, every_version_and_point_format_reads_positions_intensity_classification_and_colours) {
  const struct {
    unsigned minor, format;
    std::size_t extra_bytes;
  } cases[] = {{2, 0, 0}, {2, 1, 0}, {2, 2, 0}, {2, 3, 0}, {0, 1, 0}, {3, 5, 4}, {4, 6, 0},
               {4, 7, 0}, {4, 8, 2}, {4, 9, 0}, {4, 10, 5}, {2, 2, 7}};
  const auto points = three_points();
  for (const auto& c : cases) {
    SCOPED_TRACE("LAS 1." + std::to_string(c.minor) + " format " + std::to_string(c.format) + " extra " +
                 std::to_string(c.extra_bytes));
    LasLayout layout;
    layout.minor = c.minor;
    layout.format = c.format;
    layout.extra_bytes = c.extra_bytes;
    layout.offset = {10.0, -20.0, 0.5};
    const AttributedPoints read = read_attributed_points(write_las("p.las", points, layout));
    ASSERT_EQ(read.points.size(), 3U);
    EXPECT_FALSE(read.points.has_normals());
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_NEAR(read.points.points[i].x(), points[i].x, 1e-12);
      EXPECT_NEAR(read.points.points[i].y(), points[i].y, 1e-12);
      EXPECT_NEAR(read.points.points[i].z(), points[i].z, 1e-12);
    }
    EXPECT_EQ(scalar(read, "intensity"), (std::vector<float>{100, 65535, 0}));
    EXPECT_EQ(scalar(read, "classification"), (std::vector<float>{2, 6, 1}));
    const bool has_rgb = c.format == 2 || c.format == 3 || c.format == 5 || c.format == 7 || c.format == 8 ||
                         c.format == 10;
    ASSERT_EQ(read.attributes.colours.size(), has_rgb ? 3U : 0U);
    if (has_rgb) {
      // All within 0..255: 8-bit values stored unscaled.
      EXPECT_EQ(read.attributes.colours[0], (Colour{255, 0, 10}));
      EXPECT_EQ(read.attributes.colours[1], (Colour{0, 128, 255}));
      EXPECT_EQ(read.attributes.colours[2], (Colour{17, 34, 51}));
    }
  }
}

TEST_F(LasReader, scale_and_offset_are_applied_per_axis) {
  LasLayout layout;
  layout.scale = {0.01, 0.5, 2.0};
  layout.offset = {500000.0, 5000000.0, -100.0};
  const AttributedPoints read =
      read_attributed_points(write_las("s.las", {{500001.23, 5000003.5, -90.0}, {499999.0, 4999999.0, 0.0}}, layout));
  ASSERT_EQ(read.points.size(), 2U);
  testing::expect_same_point(Point3(123 * 0.01 + 500000.0, 7 * 0.5 + 5000000.0, 5 * 2.0 - 100.0),
                             read.points.points[0]);
  testing::expect_same_point(Point3(-100 * 0.01 + 500000.0, -2 * 0.5 + 5000000.0, 50 * 2.0 - 100.0),
                             read.points.points[1]);
}

TEST_F(LasReader, sixteen_bit_colours_are_scaled_down) {
  auto points = three_points();
  points[0].rgb = {65535, 0, 257 * 10};
  points[1].rgb = {0, 257 * 128, 65535};
  const AttributedPoints read = read_attributed_points(write_las("c.las", points));
  ASSERT_EQ(read.attributes.colours.size(), 3U);
  EXPECT_EQ(read.attributes.colours[0], (Colour{255, 0, 10}));
  EXPECT_EQ(read.attributes.colours[1], (Colour{0, 128, 255}));
  EXPECT_EQ(read.attributes.colours[2], (Colour{0, 0, 0}));  // 17, 34, 51 of 65535
}

TEST_F(LasReader, legacy_formats_read_the_class_without_its_flag_bits) {
  auto points = three_points();
  points[0].classification = 0x80 | 2;  // withheld, ground
  points[1].classification = 0x40 | 6;  // key-point, building
  LasLayout legacy;
  legacy.format = 1;
  EXPECT_EQ(scalar(read_attributed_points(write_las("l.las", points, legacy)), "classification"),
            (std::vector<float>{2, 6, 1}));
  LasLayout extended;
  extended.minor = 4;
  extended.format = 6;
  EXPECT_EQ(scalar(read_attributed_points(write_las("e.las", points, extended)), "classification"),
            (std::vector<float>{130, 70, 1}));
}

TEST_F(LasReader, bytes_between_the_header_and_the_points_are_skipped) {
  LasLayout layout;
  layout.gap_bytes = 54 + 100;  // a VLR header and its data
  const AttributedPoints read = read_attributed_points(write_las("v.las", three_points(), layout));
  ASSERT_EQ(read.points.size(), 3U);
  EXPECT_NEAR(read.points.points[2].x(), -7.75, 1e-12);
}

TEST_F(LasReader, a_las_14_file_counts_points_in_64_bits) {
  LasLayout layout;
  layout.minor = 4;
  layout.format = 7;
  const auto file = write_las("c.las", three_points(), layout);
  EXPECT_EQ(read_attributed_points(file).points.size(), 3U);
  // The 64-bit count beyond the points there are is refused, although the legacy count is 0.
  layout.announced_count = 4;
  EXPECT_EQ(problem(write_las("d.las", three_points(), layout)),
            "truncated point data: the header announces 4 points of 36 bytes, the file holds 3");
}

TEST_F(LasReader, compressed_files_are_refused_naming_ways_to_decompress_them) {
  const auto laz = write_las("scan.laz", three_points());
  const std::string to = path("scan.las").string();
  EXPECT_EQ(problem(laz), "compressed LAS (LAZ) is not read; decompress it first, e.g. with `laszip -i " +
                              laz.string() + " -o " + to + "` or `pdal translate " + laz.string() + " " + to + "`");
  LasLayout layout;
  layout.compressed = true;
  const auto marked = write_las("marked.las", three_points(), layout);
  const std::string out = path("marked-decompressed.las").string();
  EXPECT_EQ(problem(marked), "compressed LAS (LAZ) is not read; decompress it first, e.g. with `laszip -i " +
                                 marked.string() + " -o " + out + "` or `pdal translate " + marked.string() + " " +
                                 out + "`");
}

TEST_F(LasReader, broken_headers_and_counts_are_refused_in_one_line) {
  const std::string good = fixtures::las_bytes(three_points());
  EXPECT_EQ(problem(write("a.las", "PLY\n")), "not a LAS file (it does not start with 'LASF')");
  EXPECT_EQ(problem(write("b.las", good.substr(0, 100))), "truncated header (100 bytes; a LAS header has at least 227)");
  LasLayout v14;
  v14.minor = 4;
  v14.format = 6;
  EXPECT_EQ(problem(write("c.las", fixtures::las_bytes(three_points(), v14).substr(0, 300))),
            "truncated header (300 bytes; a LAS 1.4 header has 375)");
  std::string version = good;
  version[24] = 2;
  version[25] = 0;
  EXPECT_EQ(problem(write("d.las", version)), "LAS version 2.0 is not read (1.0 to 1.4 are)");
  std::string small_header = good;
  fixtures::put_le<std::uint16_t>(small_header, 94, 200);
  EXPECT_EQ(problem(write("e.las", small_header)), "header size 200 is below the 227 bytes of a LAS 1.2 header");
  std::string format = good;
  format[104] = 11;
  EXPECT_EQ(problem(write("f.las", format)), "point data format 11 is not defined (0 to 10 are)");
  LasLayout short_records;
  short_records.format = 3;
  short_records.record_length = 28;
  EXPECT_EQ(problem(write_las("g.las", three_points(), short_records)),
            "point record length 28 is too small for point data format 3 (34 bytes)");
  LasLayout too_many;
  too_many.announced_count = 1000;
  EXPECT_EQ(problem(write_las("h.las", three_points(), too_many)),
            "truncated point data: the header announces 1000 points of 26 bytes, the file holds 3");
  EXPECT_EQ(problem(write("i.las", good.substr(0, good.size() - 1))),
            "truncated point data: the header announces 3 points of 26 bytes, the file holds 2");
  LasLayout none;
  none.announced_count = 0;
  EXPECT_EQ(problem(write_las("j.las", three_points(), none)), "no points");
  std::string inside = good;
  fixtures::put_le<std::uint32_t>(inside, 96, 100);
  EXPECT_EQ(problem(write("k.las", inside)), "point data offset 100 lies inside the 227-byte header");
  std::string beyond = good;
  fixtures::put_le<std::uint32_t>(beyond, 96, 100000);
  EXPECT_EQ(problem(write("l.las", beyond)), "point data offset 100000 is beyond the end of the file (305 bytes)");
  std::string zero_scale = good;
  fixtures::put_le<double>(zero_scale, 139, 0.0);
  EXPECT_EQ(problem(write("m.las", zero_scale)), "y scale factor 0 is not a usable scale");
  std::string huge = good;
  fixtures::put_le<double>(huge, 147, 1e300);
  EXPECT_EQ(problem(write("n.las", huge)), "point 1: coordinate beyond 1e30 in magnitude: scale the input down");
}

TEST_F(LasReader, any_truncation_of_a_valid_file_is_read_or_refused_in_one_line) {
  LasLayout layout;
  layout.minor = 4;
  layout.format = 10;
  const std::string bytes = fixtures::las_bytes(three_points(), layout);
  for (std::size_t size = 0; size < bytes.size(); size += 7) {
    const auto file = write("t.las", bytes.substr(0, size));
    testing::expect_read_or_one_line_refusal(file, "read_attributed_points", [&] { read_attributed_points(file); });
  }
}

}  // namespace
}  // namespace envcrust::io
