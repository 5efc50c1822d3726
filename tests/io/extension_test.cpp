// Tests of format dispatch by extension and of the messages for files that cannot be opened.
#include "envcrust/io.h"
#include "io_test_support.h"

namespace envcrust::io {
namespace {

using testing::io_error_of;

class Extension : public testing::TempDirTest {};

TEST(ExtensionOf, is_lower_case_without_dot) {
  EXPECT_EQ(extension_of("a/b/scan.PLY"), "ply");
  EXPECT_EQ(extension_of("scan.xyz"), "xyz");
  EXPECT_EQ(extension_of("archive.tar.gz"), "gz");
  EXPECT_EQ(extension_of("noext"), "");
  EXPECT_EQ(extension_of(".hidden"), "");
}

TEST_F(Extension, read_points_names_unknown_extension_and_expected_ones) {
  const auto file = write("a.foo", "1 2 3\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() +
                ": unknown extension '.foo' (expected .xyz, .pts, .txt, .csv, .ply, .off, .obj, .stl, .las)");
}

TEST_F(Extension, read_points_reports_missing_extension) {
  const auto file = write("points", "1 2 3\n");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ": no extension (expected .xyz, .pts, .txt, .csv, .ply, .off, .obj, .stl, .las)");
}

TEST_F(Extension, read_polygon_mesh_names_unknown_extension) {
  const auto file = write("a.xyz", "1 2 3\n");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(file); }),
            file.string() + ": unknown extension '.xyz' (expected .off, .obj, .ply, .stl)");
}

TEST_F(Extension, writers_name_unknown_extension) {
  const TriangleMesh mesh{{Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)}, {{0, 1, 2}}};
  const auto mesh_file = path("a.stp");
  EXPECT_EQ(io_error_of([&] { write_mesh(mesh_file, mesh); }),
            mesh_file.string() + ": unknown extension '.stp' (expected .ply, .off, .obj, .stl)");
  const auto points_file = path("a.off");
  EXPECT_EQ(io_error_of([&] { write_points(points_file, PointSet{{Point3(0, 0, 0)}, {}}); }),
            points_file.string() + ": unknown extension '.off' (expected .xyz, .ply)");
  const auto curve_file = path("a.txt");
  EXPECT_EQ(io_error_of([&] { write_polyline(curve_file, {Point3(0, 0, 0)}); }),
            curve_file.string() + ": unknown extension '.txt' (expected .polyline, .xyz)");
  EXPECT_TRUE(files().empty());
}

TEST_F(Extension, missing_file_cannot_be_opened) {
  const auto file = path("missing.xyz");
  EXPECT_EQ(io_error_of([&] { read_points(file); }), file.string() + ": cannot open file");
  const auto mesh_file = path("missing.off");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(mesh_file); }),
            mesh_file.string() + ": cannot open file");
}

TEST_F(Extension, relative_path_is_reported_as_given) {
  const std::filesystem::path file = "surely/not/here.ply";
  EXPECT_EQ(io_error_of([&] { read_points(file); }), "surely/not/here.ply: cannot open file");
}

TEST_F(Extension, directory_is_not_a_file) {
  std::filesystem::create_directory(path("d.xyz"));
  const auto file = path("d.xyz");
  EXPECT_EQ(io_error_of([&] { read_points(file); }),
            file.string() + ": is a directory, not a file");
  // Without an extension it is still named a directory, not a file lacking an extension.
  std::filesystem::create_directory(path("scans"));
  EXPECT_EQ(io_error_of([&] { read_points(path("scans")); }), path("scans").string() + ": is a directory, not a file");
  EXPECT_EQ(io_error_of([&] { read_polygon_mesh(path("scans")); }),
            path("scans").string() + ": is a directory, not a file");
}

}  // namespace
}  // namespace envcrust::io
