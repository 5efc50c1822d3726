// Round trips through every writer and reader pair, compared exactly, and writer input checks.
#include "envcrust/io.h"
#include "io_test_support.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace envcrust::io {
namespace {

using testing::io_error_of;

class Writer : public testing::TempDirTest {};

// Coordinates that only survive a round trip with full double precision.
TriangleMesh awkward_mesh() {
  TriangleMesh mesh;
  mesh.vertices = {Point3(0.1, 0.2, 0.3),
                   Point3(1.0 / 3.0, -2.0 / 7.0, 1e-310),
                   Point3(123456789.123456789, std::nextafter(1.0, 2.0), -0.0),
                   Point3(std::nextafter(1e30, 0.0), std::numeric_limits<double>::min(),  // readers take |x| <= 1e30
                          -std::numeric_limits<double>::denorm_min())};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {3, 2, 1}};
  return mesh;
}

void expect_same_mesh(const TriangleMesh& expected, const TriangleMesh& actual) {
  ASSERT_EQ(expected.vertices.size(), actual.vertices.size());
  for (std::size_t v = 0; v < expected.vertices.size(); ++v) {
    testing::expect_same_point(expected.vertices[v], actual.vertices[v]);
  }
  EXPECT_EQ(expected.triangles, actual.triangles);
}

TEST_F(Writer, binary_ply_mesh_round_trips_exactly) {
  const auto file = path("m.ply");
  write_mesh(file, awkward_mesh());
  expect_same_mesh(awkward_mesh(), read_triangle_mesh(file));
}

TEST_F(Writer, binary_ply_uses_double_coordinates_and_uchar_int_faces) {
  const auto file = path("m.ply");
  write_mesh(file, awkward_mesh());
  std::ifstream in(file, std::ios::binary);
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string header = data.substr(0, data.find("end_header\n") + 11);
  EXPECT_NE(header.find("format binary_little_endian 1.0\n"), std::string::npos);
  EXPECT_NE(header.find("property double x\n"), std::string::npos);
  EXPECT_NE(header.find("property list uchar int vertex_indices\n"), std::string::npos);
  EXPECT_EQ(data.size(), header.size() + 4 * 24 + 3 * 13);
}

TEST_F(Writer, ascii_ply_mesh_round_trips_exactly) {
  const auto file = path("m.ply");
  write_mesh(file, awkward_mesh(), PlyEncoding::Ascii);
  expect_same_mesh(awkward_mesh(), read_triangle_mesh(file));
}

TEST_F(Writer, off_mesh_round_trips_exactly) {
  const auto file = path("m.off");
  write_mesh(file, awkward_mesh());
  expect_same_mesh(awkward_mesh(), read_triangle_mesh(file));
}

TEST_F(Writer, obj_mesh_round_trips_exactly) {
  const auto file = path("m.obj");
  write_mesh(file, awkward_mesh());
  expect_same_mesh(awkward_mesh(), read_triangle_mesh(file));
}

PointSet awkward_points(bool with_normals) {
  PointSet points;
  const TriangleMesh mesh = awkward_mesh();
  points.points = mesh.vertices;
  if (with_normals) {
    points.normals = {Vector3(0, 0, 1), Vector3(0.6, 0.8, 0), Vector3(1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0),
                      Vector3(-1, 0, 0)};
  }
  return points;
}

void expect_same_points(const PointSet& expected, const PointSet& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  ASSERT_EQ(expected.normals.size(), actual.normals.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    testing::expect_same_point(expected.points[i], actual.points[i]);
  }
  for (std::size_t i = 0; i < expected.normals.size(); ++i) {
    EXPECT_EQ(expected.normals[i].x(), actual.normals[i].x());
    EXPECT_EQ(expected.normals[i].y(), actual.normals[i].y());
    EXPECT_EQ(expected.normals[i].z(), actual.normals[i].z());
  }
}

TEST_F(Writer, xyz_points_round_trip_exactly_with_and_without_normals) {
  for (const bool with_normals : {false, true}) {
    const auto file = path(with_normals ? "n.xyz" : "p.xyz");
    write_points(file, awkward_points(with_normals));
    expect_same_points(awkward_points(with_normals), read_points(file));
  }
}

TEST_F(Writer, xyz_with_normals_has_six_columns) {
  const auto file = path("n.xyz");
  write_points(file, PointSet{{Point3(1, 2, 3)}, {Vector3(0, 0, 1)}});
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "1 2 3 0 0 1\n");
}

TEST_F(Writer, ply_points_round_trip_exactly_in_both_encodings) {
  for (const PlyEncoding encoding : {PlyEncoding::Binary, PlyEncoding::Ascii}) {
    for (const bool with_normals : {false, true}) {
      const auto file = path("p.ply");
      write_points(file, awkward_points(with_normals), encoding);
      expect_same_points(awkward_points(with_normals), read_points(file));
    }
  }
}

TEST_F(Writer, refuses_triangle_index_out_of_range_without_writing) {
  TriangleMesh mesh = awkward_mesh();
  mesh.triangles[1][2] = 9;
  const auto file = path("m.off");
  EXPECT_EQ(io_error_of([&] { write_mesh(file, mesh); }),
            file.string() + ": cannot write triangle 1: vertex index 9 out of range (4 vertices)");
  EXPECT_TRUE(files().empty());
}

TEST_F(Writer, refuses_non_finite_coordinates_without_writing) {
  TriangleMesh mesh = awkward_mesh();
  mesh.vertices[2] = Point3(0, std::numeric_limits<double>::infinity(), 0);
  const auto file = path("m.ply");
  EXPECT_EQ(io_error_of([&] { write_mesh(file, mesh); }),
            file.string() + ": cannot write non-finite coordinate (vertex 2)");
  const auto points_file = path("p.xyz");
  PointSet points = awkward_points(true);
  points.normals[3] = Vector3(std::nan(""), 0, 0);
  EXPECT_EQ(io_error_of([&] { write_points(points_file, points); }),
            points_file.string() + ": cannot write non-finite normal (point 3)");
  EXPECT_TRUE(files().empty());
}

TEST_F(Writer, refuses_normal_count_that_differs_from_point_count) {
  PointSet points = awkward_points(true);
  points.normals.pop_back();
  const auto file = path("p.ply");
  EXPECT_EQ(io_error_of([&] { write_points(file, points); }),
            file.string() + ": cannot write 3 normals for 4 points");
}

TEST_F(Writer, reports_missing_target_folder) {
  const auto file = path("missing/m.off");
  const std::string message = io_error_of([&] { write_mesh(file, awkward_mesh()); });
  EXPECT_EQ(message.rfind(file.string() + ": cannot create temporary file ", 0), 0U) << message;
}

}  // namespace
}  // namespace envcrust::io
