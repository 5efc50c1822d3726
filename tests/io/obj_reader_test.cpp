// Tests of the OBJ reader: face reference forms, negative indices, bad input.
#include "envcrust/io.h"
#include "io_test_support.h"

namespace envcrust::io {
namespace {

using testing::io_error_of;

class ObjReader : public testing::TempDirTest {};

TEST_F(ObjReader, reads_all_face_reference_forms_and_negative_indices) {
  const auto file = write("a.obj",
                          "# comment\n"
                          "mtllib a.mtl\n"
                          "o thing\n"
                          "v 0 0 0\n"
                          "v 1 0 0 1.0\n"
                          "v 1 1 0 0.5 0.5 0.5\n"
                          "v 0 1 0\n"
                          "vt 0 0\n"
                          "vn 0 0 1\n"
                          "usemtl red\n"
                          "s off\n"
                          "f 1/2/3 2//1 3\n"
                          "f -4 -2/1 -1//1 # quad written backwards\n"
                          "l 1 2\n");
  const PolygonMesh mesh = read_polygon_mesh(file);
  ASSERT_EQ(mesh.vertices.size(), 4U);
  testing::expect_same_point(Point3(1, 1, 0), mesh.vertices[2]);
  ASSERT_EQ(mesh.faces.size(), 2U);
  EXPECT_EQ(mesh.faces[0], (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(mesh.faces[1], (std::vector<Index>{0, 2, 3}));
  // one vertex with a colour: no colours
  EXPECT_FALSE(read_attributed_points(file).attributes.has_colours());
}

// MeshLab's vertex colours, "v x y z r g b" in 0..1 (or 0..255 when some value is above 1).
TEST_F(ObjReader, reads_vertex_colours_when_every_vertex_has_one) {
  const auto fractions = write("a.obj", "v 0 0 0 1 0.5 0\nv 1 0 0 0 0 1\nv 0 1 0 0.2 0.4 0.6\nf 1 2 3\n");
  const AttributedPoints a = read_attributed_points(fractions);
  EXPECT_EQ(a.attributes.colours, (std::vector<Colour>{{255, 128, 0}, {0, 0, 255}, {51, 102, 153}}));
  const auto bytes = write("b.obj", "v 0 0 0 255 128 0\nv 1 0 0 0 0 1\nv 0 1 0 1 1 1\nf 1 2 3\n");
  EXPECT_EQ(read_attributed_points(bytes).attributes.colours.at(0), (Colour{255, 128, 0}));
  EXPECT_EQ(read_attributed_points(bytes).attributes.colours.at(1), (Colour{0, 0, 1}));
}

TEST_F(ObjReader, fan_triangulates_polygons) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const TriangleMesh mesh = read_triangle_mesh(file);
  ASSERT_EQ(mesh.triangles.size(), 2U);
  EXPECT_EQ(mesh.triangles[1], (std::array<Index, 3>{0, 2, 3}));
}

TEST_F(ObjReader, reports_face_index_out_of_range) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":4: face index 4 out of range (3 vertices)");
}

TEST_F(ObjReader, reports_negative_index_reaching_before_first_vertex) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":4: face index -4 out of range (3 vertices)");
}

TEST_F(ObjReader, reports_index_zero) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":4: face index 0 is invalid (OBJ indices start at 1)");
}

TEST_F(ObjReader, reports_face_with_two_vertices) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":3: face with 2 vertices (need at least 3)");
}

TEST_F(ObjReader, reports_vertex_with_two_numbers) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ":2: expected at least 3 numbers after 'v', got 2");
}

TEST_F(ObjReader, reports_infinite_coordinate) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0 -infinity\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ":2: non-finite coordinate");
}

TEST_F(ObjReader, reports_bad_reference) {
  const auto file = write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/3\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ":4: expected a vertex index, got 'x/3'");
}

TEST_F(ObjReader, reports_file_without_vertices_as_no_points) {
  const auto file = write("a.obj", "# empty\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ": no points");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }), file.string() + ": no faces");
}

}  // namespace
}  // namespace envcrust::io
