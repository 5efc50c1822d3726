// Robustness: random bytes and every truncation of valid files give IoError or data, never a crash.
#include "envcrust/io.h"
#include "io_test_support.h"

#include <fstream>
#include <random>
#include <sstream>

namespace envcrust::io {
namespace {

class GarbageInput : public testing::TempDirTest {};

// Read `file` with every reader; anything but success or IoError fails the test.
void read_everything(const std::filesystem::path& file) {
  const auto survive = [&](const char* reader, auto&& action) { testing::expect_read_or_one_line_refusal(file, reader, action); };
  survive("read_points", [&] { read_points(file); });
  survive("read_polygon_mesh", [&] { read_polygon_mesh(file); });
  survive("read_polyline", [&] { read_polyline(file); });
}

TEST_F(GarbageInput, random_bytes_never_crash_any_reader) {
  std::mt19937 random(12345);
  std::uniform_int_distribution<int> byte(0, 255);
  const std::vector<std::string> prefixes = {
      "", "ply\nformat binary_little_endian 1.0\nelement vertex 99999999999\n",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uint int vertex_indices\nend_header\n",
      "OFF\n", "solid ", "v 1 2 3\nf "};
  for (const char* extension : {".xyz", ".ply", ".off", ".obj", ".stl", ".polyline"}) {
    for (const std::string& prefix : prefixes) {
      for (int round = 0; round < 8; ++round) {
        std::string data = prefix;
        const int size = 1 + round * round * 20;
        for (int i = 0; i < size; ++i) {
          data += static_cast<char>(byte(random));
        }
        read_everything(write(std::string("g") + extension, data));
      }
    }
  }
}

TEST_F(GarbageInput, every_truncation_of_valid_files_is_handled) {
  const TriangleMesh mesh{{Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)},
                          {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}};
  write_mesh(path("full.ply"), mesh);
  write_mesh(path("full_ascii.ply"), mesh, PlyEncoding::Ascii);
  write_mesh(path("full.off"), mesh);
  write_mesh(path("full.obj"), mesh);
  for (const char* name : {"full.ply", "full_ascii.ply", "full.off", "full.obj"}) {
    std::ifstream in(path(name), std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string data = buffer.str();
    const std::string extension = std::filesystem::path(name).extension().string();
    for (std::size_t size = 0; size < data.size(); ++size) {
      read_everything(write("cut" + extension, data.substr(0, size)));
    }
  }
}

TEST_F(GarbageInput, random_byte_flips_of_valid_files_are_handled) {
  const TriangleMesh mesh{{Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)},
                          {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}};
  write_mesh(path("full.ply"), mesh);
  write_points(path("points.ply"), PointSet{mesh.vertices, {}}, PlyEncoding::Ascii);
  write_mesh(path("full.off"), mesh);
  std::mt19937 random(777);
  for (const char* name : {"full.ply", "points.ply", "full.off"}) {
    std::ifstream in(path(name), std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string data = buffer.str();
    const std::string extension = std::filesystem::path(name).extension().string();
    std::uniform_int_distribution<std::size_t> position(0, data.size() - 1);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int round = 0; round < 120; ++round) {
      std::string mutated = data;
      for (int flip = 0; flip < 1 + round % 4; ++flip) {
        mutated[position(random)] = static_cast<char>(byte(random));
      }
      read_everything(write("flip" + extension, mutated));
    }
  }
}

}  // namespace
}  // namespace envcrust::io
