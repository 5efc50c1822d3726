// Writer of triangle meshes with per-vertex data (normals, colours, scalars): PLY and OBJ
// carry it, OFF and STL get the mesh alone.
#include "envcrust/io.h"

#include "io_detail.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <ostream>
#include <set>
#include <type_traits>

namespace envcrust::io {
namespace {

void append_float(std::string& out, float value) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), ec == std::errc() ? end : buffer.data());
}

// Float32 positions halve the file, and round a coordinate c by at most c * 2^-24: kept while
// that stays within 1e-6 of the mesh's diagonal. A georeferenced scan (coordinates of 500,000
// for a 10 m object) would be rounded by 3 cm and gets float64.
bool positions_fit_float(const std::vector<Point3>& vertices) {
  if (vertices.empty()) return true;
  double low[3], high[3], largest = 0;
  for (int a = 0; a < 3; ++a) low[a] = high[a] = vertices.front()[a];
  for (const Point3& p : vertices) {
    for (int a = 0; a < 3; ++a) {
      low[a] = std::min(low[a], p[a]);
      high[a] = std::max(high[a], p[a]);
      largest = std::max(largest, std::abs(p[a]));
    }
  }
  const double diagonal = std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  return largest * 0x1p-24 <= 1e-6 * diagonal || largest == 0;
}

// PLY property names for the scalars: one token each (white space and empties replaced) and
// none repeated nor equal to a name the writer uses for positions, normals and colours.
std::vector<std::string> ply_scalar_names(const std::vector<std::string>& names) {
  std::set<std::string> used = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"};
  std::vector<std::string> out;
  for (std::string name : names) {
    if (name.empty()) name = "scalar";
    std::replace_if(name.begin(), name.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
    std::string unique = name;
    for (int k = 2; used.count(unique) > 0; ++k) unique = name + "_" + std::to_string(k);
    used.insert(unique);
    out.push_back(unique);
  }
  return out;
}

void write_ply(std::ostream& out, const TriangleMesh& mesh, const MeshVertexData& data, PlyEncoding encoding) {
  const bool binary = encoding == PlyEncoding::Binary;
  const bool as_float = positions_fit_float(mesh.vertices);
  const PointAttributes& attributes = data.attributes;
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment written by envcrust\n"
      << "element vertex " << mesh.vertices.size() << "\n";
  for (const char* axis : {"x", "y", "z"}) out << "property " << (as_float ? "float " : "double ") << axis << "\n";
  if (!data.normals.empty()) out << "property float nx\nproperty float ny\nproperty float nz\n";
  if (attributes.has_colours()) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  for (const std::string& name : ply_scalar_names(attributes.names)) out << "property float " << name << "\n";
  out << "element face " << mesh.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  std::string buffer;
  // One value of a record: binary bytes, or ascii text after a space but for the first.
  auto put = [&](auto value, bool first) {
    if (binary) {
      detail::append_little_endian(buffer, value);
      return;
    }
    if (!first) buffer += ' ';
    if constexpr (std::is_same_v<decltype(value), float>) {
      append_float(buffer, value);
    } else if constexpr (std::is_same_v<decltype(value), double>) {
      detail::append_double(buffer, value);
    } else {
      buffer += std::to_string(value);
    }
  };
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Point3& p = mesh.vertices[v];
    for (int a = 0; a < 3; ++a) {
      if (as_float) {
        put(static_cast<float>(p[a]), a == 0);
      } else {
        put(p[a], a == 0);
      }
    }
    if (!data.normals.empty())
      for (int a = 0; a < 3; ++a) put(static_cast<float>(data.normals[v][a]), false);
    if (attributes.has_colours())
      for (const std::uint8_t c : attributes.colours[v]) put(c, false);
    for (const auto& column : attributes.scalars) put(column[v], false);
    if (!binary) buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  for (const auto& triangle : mesh.triangles) {
    put(std::uint8_t{3}, true);
    for (const Index v : triangle) put(static_cast<std::int32_t>(v), false);
    if (!binary) buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  detail::flush_buffer(out, buffer, true);
}

// OBJ has no standard vertex colour: "v x y z r g b" with colours in 0..1 is the extension
// MeshLab and CloudCompare write and read. Faces name each corner's normal (f a//a ...).
void write_obj(std::ostream& out, const TriangleMesh& mesh, const MeshVertexData& data) {
  out << "# written by envcrust\n";
  std::string buffer;
  const bool colours = data.attributes.has_colours();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    buffer += "v ";
    detail::append_point(buffer, mesh.vertices[v]);
    if (colours)
      for (const std::uint8_t c : data.attributes.colours[v]) {
        buffer += ' ';
        append_float(buffer, static_cast<float>(c) / 255.0F);
      }
    buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  for (const Vector3& n : data.normals) {
    buffer += "vn";
    for (int a = 0; a < 3; ++a) {
      buffer += ' ';
      append_float(buffer, static_cast<float>(n[a]));
    }
    buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  for (const auto& triangle : mesh.triangles) {
    buffer += "f";
    for (const Index v : triangle) {
      const std::string i = std::to_string(std::uint64_t{v} + 1);  // OBJ counts vertices from 1
      buffer += ' ' + i + (data.normals.empty() ? "" : "//" + i);
    }
    buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  detail::flush_buffer(out, buffer, true);
}

void check_vertex_data(const std::filesystem::path& path, const TriangleMesh& mesh, const MeshVertexData& data) {
  const std::size_t n = mesh.vertices.size();
  auto check = [&](std::size_t size, const std::string& what) {
    if (size != 0 && size != n)
      detail::fail(path, "cannot write " + std::to_string(size) + " " + what + " for " + std::to_string(n) +
                             " vertices");
  };
  check(data.normals.size(), "normals");
  check(data.attributes.colours.size(), "colours");
  if (data.attributes.names.size() != data.attributes.scalars.size())
    detail::fail(path, "cannot write " + std::to_string(data.attributes.scalars.size()) + " scalar columns under " +
                           std::to_string(data.attributes.names.size()) + " names");
  for (std::size_t c = 0; c < data.attributes.scalars.size(); ++c) {
    if (const std::size_t size = data.attributes.scalars[c].size(); size != n)
      detail::fail(path, "cannot write " + std::to_string(size) + " values of '" + data.attributes.names[c] +
                             "' for " + std::to_string(n) + " vertices");
  }
}

}  // namespace

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, const MeshVertexData& data,
                PlyEncoding encoding) {
  const std::string extension = extension_of(path);
  if (extension != "ply" && extension != "obj") {
    write_mesh(path, mesh, encoding);  // OFF and STL hold no vertex data
    return;
  }
  detail::check_mesh(path, mesh, extension == "ply");
  check_vertex_data(path, mesh, data);
  if (extension == "ply") {
    write_atomic(path, encoding == PlyEncoding::Binary,
                 [&](std::ostream& out) { write_ply(out, mesh, data, encoding); });
  } else {
    write_atomic(path, false, [&](std::ostream& out) { write_obj(out, mesh, data); });
  }
}

}  // namespace envcrust::io
