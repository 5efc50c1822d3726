// Tests of the PLY reader: ascii and both binary byte orders, skipped properties, bad input.
#include "envcrust/io.h"
#include "io_test_support.h"

#include <cstdint>

namespace envcrust::io {
namespace {

using testing::Bytes;
using testing::io_error_of;

class PlyReader : public testing::TempDirTest {};

TEST_F(PlyReader, reads_ascii_mesh_and_skips_unknown_properties_and_elements) {
  const auto file = write("a.ply",
                          "ply\n"
                          "format ascii 1.0\n"
                          "comment made by hand\n"
                          "obj_info nothing\n"
                          "element vertex 4\n"
                          "property float x\n"
                          "property uchar red\n"
                          "property float y\n"
                          "property list uchar int tags\n"
                          "property double z\n"
                          "element face 1\n"
                          "property int flags\n"
                          "property list uchar int vertex_indices\n"
                          "element edge 1\n"
                          "property int vertex1\n"
                          "property int vertex2\n"
                          "end_header\n"
                          "0 255 0 2 7 8 0.5\n"
                          "1 0 0 0 0.25\n"
                          "1 1 1 1 5 0\n"
                          "0 2 1 0 -1.5e2\n"
                          "9 4 0 1 2 3\n"
                          "0 1\n");
  const PolygonMesh mesh = read_polygon_mesh(file);
  ASSERT_EQ(mesh.vertices.size(), 4U);
  testing::expect_same_point(Point3(0, 0, 0.5), mesh.vertices[0]);
  testing::expect_same_point(Point3(1, 0, 0.25), mesh.vertices[1]);
  testing::expect_same_point(Point3(1, 1, 0), mesh.vertices[2]);
  testing::expect_same_point(Point3(0, 1, -150), mesh.vertices[3]);
  ASSERT_EQ(mesh.faces.size(), 1U);
  EXPECT_EQ(mesh.faces[0], (std::vector<Index>{0, 1, 2, 3}));
}

TEST_F(PlyReader, fan_triangulates_polygons) {
  const auto file = write("a.ply",
                          "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\n"
                          "property float y\nproperty float z\nelement face 1\n"
                          "property list uchar uint vertex_index\nend_header\n"
                          "0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 0 1 2 3 4\n");
  const TriangleMesh mesh = read_triangle_mesh(file);
  ASSERT_EQ(mesh.triangles.size(), 3U);
  EXPECT_EQ(mesh.triangles[0], (std::array<Index, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<Index, 3>{0, 2, 3}));
  EXPECT_EQ(mesh.triangles[2], (std::array<Index, 3>{0, 3, 4}));
}

TEST_F(PlyReader, reads_ascii_header_with_crlf_line_ends) {
  const auto file = write("a.ply",
                          "ply\r\nformat ascii 1.0\r\nelement vertex 1\r\nproperty float x\r\n"
                          "property float y\r\nproperty float z\r\nend_header\r\n1 2 3\r\n");
  const PointSet points = read_points(file);
  ASSERT_EQ(points.size(), 1U);
  testing::expect_same_point(Point3(1, 2, 3), points.points[0]);
}

std::string little_endian_cloud() {
  Bytes bytes(false);
  bytes.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\n"
      "property float x\nproperty float y\nproperty float z\n"
      "property list uchar float junk\nproperty uchar red\n"
      "property double nx\nproperty double ny\nproperty double nz\n"
      "element face 1\nproperty list uchar uint vertex_indices\nproperty short flags\n"
      "element material 2\nproperty list int ushort ids\nend_header\n");
  bytes.put(0.5F).put(-1.25F).put(3.0F).put(std::uint8_t{2}).put(9.0F).put(9.0F);
  bytes.put(std::uint8_t{7}).put(0.0).put(0.0).put(1.0);
  bytes.put(1e29F).put(2.0F).put(-3.0F).put(std::uint8_t{0});
  bytes.put(std::uint8_t{1}).put(0.0).put(1.0).put(0.0);
  bytes.put(std::uint8_t{3}).put(std::uint32_t{0}).put(std::uint32_t{1}).put(std::uint32_t{1});
  bytes.put(std::int16_t{-1});
  bytes.put(std::int32_t{1}).put(std::uint16_t{4}).put(std::int32_t{0});
  return bytes.str();
}

TEST_F(PlyReader, reads_binary_little_endian_points_with_normals) {
  const PointSet points = read_points(write("a.ply", little_endian_cloud()));
  ASSERT_EQ(points.size(), 2U);
  testing::expect_same_point(Point3(0.5, -1.25, 3), points.points[0]);
  testing::expect_same_point(Point3(static_cast<double>(1e29F), 2, -3), points.points[1]);
  ASSERT_TRUE(points.has_normals());
  EXPECT_EQ(points.normals[0], Vector3(0, 0, 1));
  EXPECT_EQ(points.normals[1], Vector3(0, 1, 0));
}

TEST_F(PlyReader, reads_binary_big_endian_mesh_with_double_coordinates) {
  Bytes bytes(true);
  bytes.text(
      "ply\nformat binary_big_endian 1.0\nelement vertex 4\n"
      "property double x\nproperty double y\nproperty double z\n"
      "element face 2\nproperty list int int vertex_indices\nend_header\n");
  const double coordinates[4][3] = {{0.1, 0.2, 0.3}, {1, 0, 0}, {1, 1, 1e-310}, {0, 1, -7}};
  for (const auto& c : coordinates) {
    bytes.put(c[0]).put(c[1]).put(c[2]);
  }
  bytes.put(std::int32_t{3}).put(std::int32_t{0}).put(std::int32_t{1}).put(std::int32_t{2});
  bytes.put(std::int32_t{4}).put(std::int32_t{0}).put(std::int32_t{1}).put(std::int32_t{2})
      .put(std::int32_t{3});
  const PolygonMesh mesh = read_polygon_mesh(write("a.ply", bytes.str()));
  ASSERT_EQ(mesh.vertices.size(), 4U);
  for (int v = 0; v < 4; ++v) {
    testing::expect_same_point(Point3(coordinates[v][0], coordinates[v][1], coordinates[v][2]),
                               mesh.vertices[v]);
  }
  ASSERT_EQ(mesh.faces.size(), 2U);
  EXPECT_EQ(mesh.faces[0], (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(mesh.faces[1], (std::vector<Index>{0, 1, 2, 3}));
}

// Colours (uchar, 16-bit, float) and every other scalar vertex property are attributes named
// like the property; lists are not.
TEST_F(PlyReader, reads_colours_and_keeps_other_vertex_properties_as_scalars) {
  const auto ascii = write("a.ply",
                           "ply\nformat ascii 1.0\nelement vertex 2\n"
                           "property float x\nproperty float y\nproperty float z\n"
                           "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
                           "property float intensity\nproperty list uchar int tags\nproperty short scan_id\n"
                           "end_header\n"
                           "0 0 0 255 128 0 200 0.5 2 1 2 7\n"
                           "1 0 0 1 2 3 255 -1 0 -3\n");
  const AttributedPoints points = read_attributed_points(ascii);
  ASSERT_EQ(points.points.size(), 2U);
  ASSERT_TRUE(points.attributes.has_colours());
  EXPECT_EQ(points.attributes.colours[0], (Colour{255, 128, 0}));
  EXPECT_EQ(points.attributes.colours[1], (Colour{1, 2, 3}));
  EXPECT_EQ(points.attributes.names, (std::vector<std::string>{"alpha", "intensity", "scan_id"}));
  EXPECT_EQ(points.attributes.scalars[1], (std::vector<float>{0.5F, -1.0F}));
  EXPECT_EQ(points.attributes.scalars[2], (std::vector<float>{7.0F, -3.0F}));
  // float colours in 0..1 and 16-bit ones, binary
  const auto binary = write("b.ply", Bytes()
                                         .text("ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                                               "property float x\nproperty float y\nproperty float z\n"
                                               "property float red\nproperty float green\nproperty ushort blue\n"
                                               "end_header\n")
                                         .put(1.0F).put(2.0F).put(3.0F)
                                         .put(1.0F).put(0.5F).put(std::uint16_t{65535})
                                         .str());
  EXPECT_EQ(read_attributed_points(binary).attributes.colours.at(0), (Colour{255, 128, 255}));
}

TEST_F(PlyReader, reports_truncated_binary_vertex_data) {
  std::string data = little_endian_cloud();
  data.resize(data.find("end_header\n") + 11 + 30);  // inside the first vertex's normal
  const auto file = write("a.ply", data);
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ": truncated binary data (vertex 0 of 2)");
}

TEST_F(PlyReader, reports_truncated_binary_face_data) {
  Bytes bytes(false);
  bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
             "property double y\nproperty double z\nelement face 2\n"
             "property list uchar int vertex_indices\nend_header\n");
  for (int i = 0; i < 9; ++i) {
    bytes.put(static_cast<double>(i));
  }
  bytes.put(std::uint8_t{3}).put(std::int32_t{0}).put(std::int32_t{1}).put(std::int32_t{2});
  bytes.put(std::uint8_t{3}).put(std::int32_t{0});
  const auto file = write("a.ply", bytes.str());
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": truncated binary data (face 1 of 2)");
}

TEST_F(PlyReader, refuses_huge_vertex_count_without_allocating) {
  Bytes bytes(false);
  bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
             "property double x\nproperty double y\nproperty double z\nend_header\n");
  for (int i = 0; i < 7; ++i) {
    bytes.put(1.0);
  }
  const auto file = write("a.ply", bytes.str());
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ": truncated binary data (vertex 2 of 4000000000)");
}

TEST_F(PlyReader, refuses_vertex_count_beyond_index_range) {
  const auto file = write("a.ply",
                          "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                          "property double x\nproperty double y\nproperty double z\nend_header\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() +
                ":3: bad PLY header: 1000000000000 vertices exceed the limit of 4294967295");
}

TEST_F(PlyReader, reports_huge_face_count_as_truncated) {
  Bytes bytes(false);
  bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1000000000000\n"
             "property list uchar int vertex_indices\nend_header\n");
  for (int i = 0; i < 9; ++i) {
    bytes.put(0.0F);
  }
  bytes.put(std::uint8_t{3}).put(std::int32_t{0}).put(std::int32_t{1}).put(std::int32_t{2});
  const auto file = write("a.ply", bytes.str());
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": truncated binary data (face 1 of 1000000000000)");
}

TEST_F(PlyReader, reports_huge_list_length_as_truncated) {
  Bytes bytes(false);
  bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1\n"
             "property list int int vertex_indices\nend_header\n");
  for (int i = 0; i < 9; ++i) {
    bytes.put(0.0F);
  }
  bytes.put(std::int32_t{2000000000}).put(std::int32_t{0});
  const auto file = write("a.ply", bytes.str());
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": truncated binary data (face 0 of 1)");
}

TEST_F(PlyReader, reports_truncated_ascii_data) {
  const auto file = write("a.ply",
                          "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                          "property float y\nproperty float z\nend_header\n1 2 3\n4 5\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ": unexpected end of file (vertex 1 of 2)");
}

TEST_F(PlyReader, reports_line_of_ascii_face_index_out_of_range) {
  const auto file = write("a.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\nelement face 2\n"
                          "property list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":14: face index 3 out of range (3 vertices)");
}

TEST_F(PlyReader, reports_binary_face_index_out_of_range) {
  Bytes bytes(false);
  bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1\n"
             "property list uchar int vertex_indices\nend_header\n");
  for (int i = 0; i < 9; ++i) {
    bytes.put(0.0F);
  }
  bytes.put(std::uint8_t{3}).put(std::int32_t{0}).put(std::int32_t{-1}).put(std::int32_t{2});
  const auto file = write("a.ply", bytes.str());
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": face 0: face index -1 out of range (3 vertices)");
}

TEST_F(PlyReader, reports_face_with_two_vertices) {
  const auto file = write("a.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\nelement face 1\n"
                          "property list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n2 0 1\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":13: face with 2 vertices (need at least 3)");
}

TEST_F(PlyReader, reports_binary_nan_coordinate_with_vertex) {
  Bytes bytes(false);
  bytes.text("ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
             "property float y\nproperty float z\nend_header\n");
  bytes.put(0.0F).put(0.0F).put(0.0F).put(1.0F).put(std::numeric_limits<float>::quiet_NaN())
      .put(0.0F);
  const auto file = write("a.ply", bytes.str());
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ": vertex 1: non-finite coordinate");
}

TEST_F(PlyReader, reports_ascii_infinite_coordinate_with_line) {
  const auto file = write("a.ply",
                          "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                          "property float y\nproperty float z\nend_header\n1 2 3\n4 inf 6\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ":9: non-finite coordinate");
}

TEST_F(PlyReader, reports_empty_vertex_element_as_no_points) {
  const auto file = write("a.ply",
                          "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                          "property float y\nproperty float z\nend_header\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ": no points");
}

struct BadHeader {
  std::string text;
  std::string problem;
};

TEST_F(PlyReader, reports_bad_headers) {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const BadHeader cases[] = {
      {"", ":1: bad PLY header: expected 'ply' on the first line"},
      {"solid x\n", ":1: bad PLY header: expected 'ply' on the first line"},
      {"ply\nformat binary 1.0\n", ":2: bad PLY header: unknown format 'binary'"},
      {"ply\nformat ascii 1.0\nelement vertex many\n",
       ":3: bad PLY header: expected 'element NAME COUNT'"},
      {"ply\nformat ascii 1.0\nelement vertex -3\n",
       ":3: bad PLY header: expected 'element NAME COUNT'"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n",
       ":4: bad PLY header: unknown property type 'float128'"},
      {"ply\nformat ascii 1.0\nproperty float x\n", ":3: bad PLY header: property before any element"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\n",
       ":4: bad PLY header: list length type must be an integer type"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float\n",
       ":4: bad PLY header: expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'"},
      {"ply\nformat ascii 1.0\nvertices 3\n", ":3: bad PLY header: unknown keyword 'vertices'"},
      {"ply\nelement vertex 1\n" + xyz + "end_header\n", ":6: bad PLY header: missing 'format' line"},
      {"ply\nformat ascii 1.0\nelement vertex 1\n" + xyz,
       ": bad PLY header: missing 'end_header'"},
      {"ply\nformat ascii 1.0\nelement point 1\n" + xyz + "end_header\n1 2 3\n",
       ": bad PLY header: no 'vertex' element"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "end_header\n1 2\n",
       ":3: bad PLY header: vertex element has no property 'z'"},
      {"ply\nformat ascii 1.0\nelement vertex 1\n" + xyz +
           "element face 0\nproperty list uchar float vertex_indices\nend_header\n1 2 3\n",
       ":7: bad PLY header: face vertex indices must have an integer type"},
      {"ply\nformat ascii 1.0\nelement vertex 1\n" + xyz +
           "element face 0\nproperty int vertex_indices\nend_header\n1 2 3\n",
       ":7: bad PLY header: face element has no list property 'vertex_indices'"},
  };
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const auto file = write("bad" + std::to_string(i) + ".ply", cases[i].text);
    EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + cases[i].problem)
        << "case " << i;
  }
}

}  // namespace
}  // namespace envcrust::io
