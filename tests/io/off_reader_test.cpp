// Tests of the OFF reader: plain OFF with comments, colour/normal variants, bad input.
#include "envcrust/io.h"
#include "io_test_support.h"

namespace envcrust::io {
namespace {

using testing::io_error_of;

class OffReader : public testing::TempDirTest {};

TEST_F(OffReader, reads_plain_off_with_comments) {
  const auto file = write("a.off",
                          "# made by hand\n"
                          "OFF\n"
                          "# counts follow\n"
                          "4 2 0\n"
                          "0 0 0\n"
                          "1 0 0 # corner\n"
                          "\n"
                          "1 1 0.125\n"
                          "0 1 -2\n"
                          "3 0 1 2\n"
                          "4 0 1 2 3\n");
  const PolygonMesh mesh = read_polygon_mesh(file);
  ASSERT_EQ(mesh.vertices.size(), 4U);
  testing::expect_same_point(Point3(1, 1, 0.125), mesh.vertices[2]);
  ASSERT_EQ(mesh.faces.size(), 2U);
  EXPECT_EQ(mesh.faces[1], (std::vector<Index>{0, 1, 2, 3}));
  const TriangleMesh triangles = read_triangle_mesh(file);
  EXPECT_EQ(triangles.triangles.size(), 3U);
}

TEST_F(OffReader, reads_counts_on_the_keyword_line_and_face_colours) {
  const auto file = write("a.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n");
  const PolygonMesh mesh = read_polygon_mesh(file);
  EXPECT_EQ(mesh.faces[0], (std::vector<Index>{0, 1, 2}));
}

TEST_F(OffReader, reads_coloured_vertices_of_coff) {
  const auto file = write("a.off", "COFF\n3 1 3\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n");
  const PolygonMesh mesh = read_polygon_mesh(file);
  ASSERT_EQ(mesh.vertices.size(), 3U);
  testing::expect_same_point(Point3(1, 0, 0), mesh.vertices[1]);
}

TEST_F(OffReader, returns_vertices_as_points) {
  const auto file = write("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const PointSet points = read_points(file);
  EXPECT_EQ(points.size(), 3U);
  EXPECT_FALSE(points.has_normals());
}

TEST_F(OffReader, refuses_unsupported_variants_clearly) {
  const auto file = write("a.off", "4OFF\n1 0 0\n0 0 0 1\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":1: unsupported OFF variant '4OFF' (supported: OFF, COFF, NOFF, CNOFF)");
  const auto binary = write("b.off", "OFF BINARY\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(binary); }),
            binary.string() + ":1: binary OFF is not supported");
}

TEST_F(OffReader, reports_wrong_keyword) {
  const auto file = write("a.off", "PLY\n3 1 0\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":1: expected 'OFF', got 'PLY'");
}

TEST_F(OffReader, reports_face_index_out_of_range) {
  const auto file = write("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n# face\n3 0 1 12\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":7: face index 12 out of range (3 vertices)");
}

TEST_F(OffReader, reports_vertex_with_wrong_column_count) {
  const auto file = write("a.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":4: expected 3 numbers for vertex 1, got 2");
}

TEST_F(OffReader, an_index_beyond_64_bits_is_not_an_index) {
  // It read as -9223372036854775808 before (wrapped through a double).
  const auto file = write("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999999999999\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":6: expected a vertex index, got '99999999999999999999'");
}

TEST_F(OffReader, reports_a_coordinate_too_large_to_compute_with) {
  const auto file = write("a.off", "OFF\n3 1 0\n0 0 0\n1 -1e308 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":4: coordinate beyond 1e30 in magnitude: scale the input down");
}

TEST_F(OffReader, reports_nan_coordinate) {
  const auto file = write("a.off", "OFF\n3 1 0\n0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":4: non-finite coordinate");
}

TEST_F(OffReader, reports_short_face) {
  const auto file = write("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":6: face of size 4 lists 3 indices");
}

TEST_F(OffReader, reports_missing_faces_as_end_of_file) {
  const auto file = write("a.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": unexpected end of file (face 1 of 2)");
}

TEST_F(OffReader, reports_huge_counts_as_end_of_file_without_allocating) {
  const auto file = write("a.off", "OFF\n4000000000 1 0\n0 0 0\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": unexpected end of file (vertex 1 of 4000000000)");
}

TEST_F(OffReader, reports_bad_counts) {
  const auto file = write("a.off", "OFF\n3\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":2: expected counts 'VERTICES FACES [EDGES]'");
}

TEST_F(OffReader, reports_empty_file) {
  const auto file = write("a.off", "# only a comment\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": empty file (expected an OFF header)");
}

TEST_F(OffReader, reports_mesh_without_faces) {
  const auto file = write("a.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }), file.string() + ": no faces");
  EXPECT_EQ(read_points(file).size(), 3U);
}

}  // namespace
}  // namespace envcrust::io
