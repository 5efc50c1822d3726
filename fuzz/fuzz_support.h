// Shared by the libFuzzer harnesses: the fuzzer's bytes as a file, the project's error rule
// checked, and the cheap stage after a reader (analyzer, normals) on small inputs.
#pragma once

#include "envcrust/analysis.h"
#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/normals.h"
#include "envcrust/nurbs_surface.h"
#include "envcrust/types.h"

#include <tbb/global_control.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>
#include <unistd.h>

namespace envcrust::fuzz {

// The stages after the reader run only below these sizes, so that one input stays far below
// the harness's -timeout (the readers themselves see every size the fuzzer makes).
inline constexpr std::size_t max_analyzed_vertices = 2000;
inline constexpr std::size_t max_analyzed_triangles = 4000;
inline constexpr std::size_t max_normal_points = 2000;
inline constexpr std::size_t max_curve_points = 300;
inline constexpr std::size_t max_nurbs_control_points = 400;

/// One thread for the stages' oneTBB loops: runs are reproducible, and a fuzzer shares the
/// machine's cores with the others.
inline void use_one_thread() {
  static tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
}

/// Where the inputs are written: /dev/shm when there is one. A file on disk made runs up to
/// 10 times slower while other jobs wrote to the disk (the writes waited on its dirty pages).
inline std::filesystem::path input_folder() {
  std::error_code ignored;
  if (std::filesystem::is_directory("/dev/shm", ignored)) return "/dev/shm";
  return std::filesystem::temp_directory_path();
}

/// The readers take a path and choose the format by extension: each input is written to one
/// file per process (several fuzzers may run at once), removed when the process ends.
class InputFile {
 public:
  explicit InputFile(const char* extension)
      : path_(input_folder() / ("envcrust-fuzz-" + std::to_string(::getpid()) + extension)) {}
  ~InputFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// Write `size` bytes at `data` to the file and return its path.
  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::fprintf(stderr, "fuzz: cannot write %s\n", path_.c_str());
      std::abort();
    }
    return path_;
  }

 private:
  std::filesystem::path path_;
};

/// The project's rule for bad input: an IoError of one line that starts with the file's name.
/// Anything else is a finding: abort, so that libFuzzer keeps the input.
inline void check_io_error(const IoError& error, const std::filesystem::path& path) {
  const std::string message = error.what();
  if (message.rfind(path.string() + ":", 0) != 0 || message.find('\n') != std::string::npos) {
    std::fprintf(stderr, "fuzz: IoError does not follow 'FILE: problem' on one line: %s\n", message.c_str());
    std::abort();
  }
}

/// Run `read` on the file; true when it accepted the bytes, false on a proper IoError.
template <class Read>
bool try_read(const std::filesystem::path& path, Read&& read) {
  try {
    read();
    return true;
  } catch (const IoError& error) {
    check_io_error(error, path);
    return false;
  }
}

/// A reader's result broke its promise (io.h): report and abort, so that libFuzzer keeps the input.
[[noreturn]] inline void broken(const char* what) {
  std::fprintf(stderr, "fuzz: accepted input gives %s\n", what);
  std::abort();
}

/// What io.h promises of an accepted file: usable coordinates (finite, within 1e30).
inline void check_coordinates(const std::vector<Point3>& points) {
  for (const Point3& p : points) {
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(p[i]) || std::abs(p[i]) > 1e30) broken("an unusable coordinate");
    }
  }
}

/// ... and a mesh's triangles index its vertices.
inline void check_mesh(const TriangleMesh& mesh) {
  check_coordinates(mesh.vertices);
  for (const auto& triangle : mesh.triangles) {
    for (const Index v : triangle) {
      if (v >= mesh.vertices.size()) broken("a triangle index out of range");
    }
  }
}

/// ... and points carry normals and attributes for all of them or none.
inline void check_points(const AttributedPoints& points) {
  const std::size_t n = points.points.size();
  if (n == 0) broken("no points");
  check_coordinates(points.points.points);
  if (!points.points.normals.empty() && points.points.normals.size() != n) broken("a normal count unlike the point count");
  if (!points.attributes.colours.empty() && points.attributes.colours.size() != n) broken("a colour count unlike the point count");
  if (points.attributes.scalars.size() != points.attributes.names.size()) broken("scalar columns unlike their names");
  for (const auto& column : points.attributes.scalars) {
    if (column.size() != n) broken("a scalar column unlike the point count");
  }
}

/// ... and balls have a radius > 0 and a label each.
inline void check_balls(const io::BallSet& balls) {
  check_coordinates(balls.centres);
  if (balls.radii.size() != balls.centres.size() || balls.labels.size() != balls.centres.size()) broken("balls without a radius or label each");
  for (const double r : balls.radii) {
    if (!std::isfinite(r) || r <= 0) broken("a radius not finite and > 0");
  }
}

/// The analyzer on a small mesh. Its own refusals (InvalidInput, DegenerateInput, ...) are
/// fine; a crash, a hang or another exception is a finding.
inline void analyze_small_mesh(const TriangleMesh& mesh) {
  if (mesh.vertices.size() > max_analyzed_vertices || mesh.triangles.size() > max_analyzed_triangles) return;
  try {
    (void)analysis::analyze_mesh(mesh);
  } catch (const Error&) {
  }
}

/// Normal estimation on a small point set, as for a point file without normals.
inline void estimate_small_normals(const PointSet& points) {
  if (points.size() > max_normal_points) return;
  try {
    (void)normals::estimate_normal_lines(points.points);
  } catch (const Error&) {
  }
}

/// The file as points, then normals.
inline void read_points(const std::filesystem::path& path) {
  AttributedPoints points;
  if (!try_read(path, [&] { points = io::read_attributed_points(path); })) return;
  check_points(points);
  estimate_small_normals(points.points);
}

/// What a mesh harness does: the file as a mesh (then the analyzer) and as points (then normals).
inline void read_mesh_and_points(const std::filesystem::path& path) {
  TriangleMesh mesh;
  if (try_read(path, [&] { mesh = io::read_triangle_mesh(path); })) {
    check_mesh(mesh);
    analyze_small_mesh(mesh);
  }
  read_points(path);
}

/// What a point-file harness does: the file as points (then normals) and as a closed curve.
inline void read_points_and_curve(const std::filesystem::path& path) {
  read_points(path);
  Polyline curve;
  if (try_read(path, [&] { curve = io::read_polyline(path); })) {
    if (curve.size() < 3) broken("a closed curve of fewer than 3 points");
    check_coordinates(curve);
  }
}

/// What a NURBS harness does: the patches, then each small one made a surface (its checks,
/// its trim loops evaluated, the knot types of its boundary).
inline void read_nurbs(const std::filesystem::path& path) {
  std::vector<surfaces::NurbsPatch> patches;
  if (!try_read(path, [&] { patches = io::read_nurbs_patches(path); })) return;
  for (surfaces::NurbsPatch& patch : patches) {
    if (patch.control_points.size() > max_nurbs_control_points) continue;
    try {
      (void)surfaces::make_nurbs_surface(std::move(patch), "fuzz");
    } catch (const Error&) {
    }
  }
}

/// The fuzzer's entry for a harness: write the bytes to a file of `extension`, run `body`.
template <class Body>
int run_input(const char* extension, const std::uint8_t* data, std::size_t size, Body&& body) {
  static InputFile file(extension);
  use_one_thread();
  body(file.write(data, size));
  return 0;
}

}  // namespace envcrust::fuzz
