// Format dispatch by file extension for the public readers, and the extension helper itself.
#include "envcrust/io.h"

#include "io_detail.h"

#include <algorithm>
#include <cctype>

namespace envcrust::io {

namespace {

detail::RawMesh read_raw_mesh(const std::filesystem::path& path, const std::string& extension) {
  if (extension == "off") {
    return detail::read_off(path);
  }
  if (extension == "obj") {
    return detail::read_obj(path);
  }
  if (extension == "ply") {
    return detail::read_ply(path);
  }
  if (extension == "stl") {
    return detail::read_stl(path);
  }
  detail::unknown_extension(path, ".off, .obj, .ply, .stl");
}

}  // namespace

std::string extension_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  if (!extension.empty() && extension.front() == '.') {
    extension.erase(0, 1);
  }
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

bool is_text_point_file(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  return extension == "xyz" || extension == "pts" || extension == "txt" || extension == "csv";
}

AttributedPoints read_attributed_points(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  if (is_text_point_file(path)) {
    return detail::read_xyz(path);
  }
  if (extension == "las" || extension == "laz") {
    return detail::read_las(path);
  }
  if (extension != "ply" && extension != "off" && extension != "obj" && extension != "stl") {
    detail::unknown_extension(path, ".xyz, .pts, .txt, .csv, .ply, .off, .obj, .stl, .las");
  }
  detail::RawMesh mesh = read_raw_mesh(path, extension);
  if (mesh.vertices.empty()) {
    detail::fail(path, "no points");
  }
  AttributedPoints result;
  result.points.points = std::move(mesh.vertices);
  result.points.normals = std::move(mesh.normals);
  result.attributes = std::move(mesh.attributes);
  return result;
}

PointSet read_points(const std::filesystem::path& path) {
  return read_attributed_points(path).points;
}

PolygonMesh read_polygon_mesh(const std::filesystem::path& path) {
  detail::RawMesh mesh = read_raw_mesh(path, extension_of(path));
  if (mesh.faces.empty()) {
    detail::fail(path, "no faces");
  }
  return PolygonMesh{std::move(mesh.vertices), std::move(mesh.faces)};
}

TriangleMesh read_triangle_mesh(const std::filesystem::path& path) {
  PolygonMesh polygons = read_polygon_mesh(path);
  TriangleMesh mesh;
  std::size_t triangle_count = 0;
  for (const auto& face : polygons.faces) {
    triangle_count += face.size() - 2;
  }
  mesh.triangles.reserve(triangle_count);
  for (const auto& face : polygons.faces) {
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      mesh.triangles.push_back({face[0], face[i], face[i + 1]});
    }
  }
  mesh.vertices = std::move(polygons.vertices);
  return mesh;
}

}  // namespace envcrust::io
