// Tests of the STL reader: ascii and binary, corner merging, truncated and bad input.
#include "envcrust/io.h"
#include "io_test_support.h"

#include <cstdint>
#include <limits>

namespace envcrust::io {
namespace {

using testing::Bytes;
using testing::io_error_of;

class StlReader : public testing::TempDirTest {};

const char* const two_facets =
    "solid square made by hand\n"
    "  facet normal 0 0 1\n"
    "    outer loop\n"
    "      vertex 0 0 0\n"
    "      vertex 1 0 0\n"
    "      vertex 1 1 0.5\n"
    "    endloop\n"
    "  endfacet\n"
    "  facet normal 0 0 1\n"
    "    outer loop\n"
    "      vertex -0 0 0\n"
    "      vertex 1 1 0.5\n"
    "      vertex 0 1 0\n"
    "    endloop\n"
    "  endfacet\n"
    "endsolid square made by hand\n";

TEST_F(StlReader, reads_ascii_and_merges_corners_by_exact_position) {
  const PolygonMesh mesh = read_polygon_mesh(write("a.stl", two_facets));
  ASSERT_EQ(mesh.vertices.size(), 4U);
  testing::expect_same_point(Point3(1, 1, 0.5), mesh.vertices[2]);
  ASSERT_EQ(mesh.faces.size(), 2U);
  EXPECT_EQ(mesh.faces[0], (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(mesh.faces[1], (std::vector<Index>{0, 2, 3}));
}

TEST_F(StlReader, reads_several_ascii_solids) {
  const std::string text = std::string(two_facets) + "solid\nfacet normal 0 0 0\nouter loop\n"
                           "vertex 5 5 5\nvertex 6 5 5\nvertex 5 6 5\nendloop\nendfacet\nendsolid\n";
  const PolygonMesh mesh = read_polygon_mesh(write("a.stl", text));
  EXPECT_EQ(mesh.vertices.size(), 7U);
  EXPECT_EQ(mesh.faces.size(), 3U);
}

std::string binary_stl(const std::string& header_start, std::uint32_t claimed,
                       const std::vector<std::array<float, 9>>& triangles) {
  std::string header = header_start;
  header.resize(80, ' ');
  Bytes bytes(false);
  bytes.text(header).put(claimed);
  for (const auto& triangle : triangles) {
    bytes.put(0.0F).put(0.0F).put(1.0F);
    for (const float value : triangle) {
      bytes.put(value);
    }
    bytes.put(std::uint16_t{0});
  }
  return bytes.str();
}

const std::vector<std::array<float, 9>> square = {
    {0, 0, 0, 1, 0, 0, 1, 1, 0.25F},
    {0, 0, 0, 1, 1, 0.25F, 0, 1, 0},
};

TEST_F(StlReader, reads_binary_and_merges_corners) {
  const PolygonMesh mesh = read_polygon_mesh(write("a.stl", binary_stl("binary", 2, square)));
  ASSERT_EQ(mesh.vertices.size(), 4U);
  testing::expect_same_point(Point3(1, 1, 0.25), mesh.vertices[2]);
  EXPECT_EQ(mesh.faces[1], (std::vector<Index>{0, 2, 3}));
  EXPECT_EQ(read_points(path("a.stl")).size(), 4U);
}

TEST_F(StlReader, reads_binary_whose_header_starts_with_solid) {
  const PolygonMesh mesh = read_polygon_mesh(write("a.stl", binary_stl("solid x", 2, square)));
  EXPECT_EQ(mesh.vertices.size(), 4U);
  EXPECT_EQ(mesh.faces.size(), 2U);
}

TEST_F(StlReader, reports_truncated_binary_data) {
  std::string data = binary_stl("binary", 3, square);
  data += std::string(20, '\0');
  const auto file = write("a.stl", data);
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": truncated binary data (triangle 2 of 3)");
}

TEST_F(StlReader, reports_truncated_binary_data_even_after_solid_header) {
  const auto file = write("a.stl", binary_stl("solid thing", 1000, square));
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": truncated binary data (triangle 2 of 1000)");
}

TEST_F(StlReader, reports_file_shorter_than_binary_header) {
  const auto file = write("a.stl", std::string(50, 'x'));
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() +
                ": truncated binary data (50-byte file, a binary STL header has 84 bytes)");
}

TEST_F(StlReader, reports_binary_nan_coordinate_with_triangle) {
  auto triangles = square;
  triangles[1][4] = std::numeric_limits<float>::quiet_NaN();
  const auto file = write("a.stl", binary_stl("binary", 2, triangles));
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": triangle 1: non-finite coordinate");
}

TEST_F(StlReader, reports_ascii_nan_coordinate_with_line) {
  std::string text = two_facets;
  text.replace(text.find("vertex 1 0 0"), 12, "vertex 1 nan 0");
  const auto file = write("a.stl", text);
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }), file.string() + ":5: non-finite coordinate");
}

TEST_F(StlReader, reports_ascii_keyword_mistake_with_line) {
  std::string text = two_facets;
  text.replace(text.find("endloop"), 7, "vortex");
  const auto file = write("a.stl", text);
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":7: expected 'vertex' or 'endloop', got 'vortex'");
}

TEST_F(StlReader, reports_truncated_ascii_file) {
  std::string text = two_facets;
  text.resize(text.find("vertex 0 1 0"));
  const auto file = write("a.stl", text);
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": unexpected end of file (facet 1)");
}

TEST_F(StlReader, reports_empty_binary_as_no_faces) {
  const auto file = write("a.stl", binary_stl("binary", 0, {}));
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }), file.string() + ": no faces");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ": no points");
}

}  // namespace
}  // namespace envcrust::io
