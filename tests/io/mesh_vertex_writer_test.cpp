// Tests of write_mesh with per-vertex data: PLY (float positions, normals, colours, scalars),
// OBJ (normals, colours), STL and OFF (the mesh alone), and data of the wrong size.
#include "envcrust/io.h"
#include "io_test_support.h"

#include <fstream>
#include <sstream>

namespace envcrust::io {
namespace {

using testing::io_error_of;

class MeshVertexWriter : public testing::TempDirTest {
 protected:
  [[nodiscard]] std::string text_of(const std::filesystem::path& file) const {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

// A unit square in the plane z = 0.1, two faces, with colours and two scalars.
TriangleMesh square(double offset = 0) {
  TriangleMesh mesh;
  mesh.vertices = {Point3(offset, 0, 0.1), Point3(offset + 1, 0, 0.1), Point3(offset + 1, 1, 0.1),
                   Point3(offset, 1, 0.1)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

MeshVertexData square_data() {
  MeshVertexData data;
  data.normals.assign(4, Vector3(0, 0, 1));
  data.attributes.colours = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {10, 20, 30}};
  data.attributes.names = {"intensity", "my column"};
  data.attributes.scalars = {{0.5F, 1.5F, -2.0F, 3.25F}, {1, 2, 3, 4}};
  return data;
}

TEST_F(MeshVertexWriter, ply_has_float_positions_normals_colours_and_scalars_in_both_encodings) {
  for (const PlyEncoding encoding : {PlyEncoding::Binary, PlyEncoding::Ascii}) {
    const auto file = path(encoding == PlyEncoding::Binary ? "b.ply" : "a.ply");
    write_mesh(file, square(), square_data(), encoding);
    const std::string data = text_of(file);
    const std::string header = data.substr(0, data.find("end_header\n"));
    for (const char* line : {"property float x\n", "property float nz\n", "property uchar red\n",
                             "property uchar blue\n", "property float intensity\n", "property float my_column\n"})
      EXPECT_NE(header.find(line), std::string::npos) << line << header;
    const AttributedPoints back = read_attributed_points(file);
    ASSERT_EQ(back.points.size(), 4U);
    // rounded to float (ascii holds the float's shortest text, which reads back as that double)
    EXPECT_EQ(static_cast<float>(back.points.points[0].z()), 0.1F);
    EXPECT_EQ(back.points.points[0].z(), encoding == PlyEncoding::Binary ? static_cast<double>(0.1F) : 0.1);
    EXPECT_EQ(back.points.normals.at(2), Vector3(0, 0, 1));
    EXPECT_EQ(back.attributes.colours, square_data().attributes.colours);
    EXPECT_EQ(back.attributes.names, (std::vector<std::string>{"intensity", "my_column"}));
    EXPECT_EQ(back.attributes.scalars, square_data().attributes.scalars);
    EXPECT_EQ(read_triangle_mesh(file).triangles, square().triangles);
  }
}

// Far from the origin for its size, float32 would move the vertices: they stay double.
TEST_F(MeshVertexWriter, ply_keeps_double_positions_far_from_the_origin) {
  const auto file = path("far.ply");
  write_mesh(file, square(500000.0), square_data());
  EXPECT_NE(text_of(file).find("property double x\n"), std::string::npos);
  EXPECT_EQ(read_points(file).points[0], Point3(500000.0, 0, 0.1));
}

TEST_F(MeshVertexWriter, obj_has_vertex_colours_and_normals) {
  const auto file = path("m.obj");
  write_mesh(file, square(), square_data());
  const std::string text = text_of(file);
  EXPECT_NE(text.find("v 0 0 0.1 1 0 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("vn 0 0 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("f 1//1 2//2 3//3\n"), std::string::npos) << text;
  EXPECT_EQ(read_triangle_mesh(file).triangles, square().triangles);
}

TEST_F(MeshVertexWriter, stl_and_off_hold_the_mesh_alone) {
  for (const char* name : {"m.stl", "m.off"}) {
    const auto file = path(name);
    write_mesh(file, square(), square_data());
    const TriangleMesh back = read_triangle_mesh(file);
    EXPECT_EQ(back.triangles.size(), 2U) << name;
    EXPECT_EQ(back.vertices.size(), 4U) << name;  // STL's corners merged again
  }
  EXPECT_EQ(text_of(path("m.stl")).size(), 80U + 4U + 2U * 50U);
}

TEST_F(MeshVertexWriter, refuses_data_of_the_wrong_size_without_writing) {
  MeshVertexData data = square_data();
  data.attributes.scalars[1].pop_back();
  const auto file = path("m.ply");
  EXPECT_EQ(io_error_of([&] { write_mesh(file, square(), data); }),
            file.string() + ": cannot write 3 values of 'my column' for 4 vertices");
  data = square_data();
  data.normals.pop_back();
  EXPECT_EQ(io_error_of([&] { write_mesh(file, square(), data); }), file.string() + ": cannot write 3 normals for 4 vertices");
  EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace envcrust::io
