// Writers of triangle meshes as PLY (binary little endian or ascii), OFF, OBJ and binary STL.
#include "envcrust/io.h"

#include "io_detail.h"

#include <cmath>
#include <ostream>

namespace envcrust::io {

namespace {

void write_ply(std::ostream& out, const TriangleMesh& mesh, PlyEncoding encoding) {
  const bool binary = encoding == PlyEncoding::Binary;
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment written by envcrust\n"
      << "element vertex " << mesh.vertices.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  std::string buffer;
  for (const Point3& p : mesh.vertices) {
    if (binary) {
      detail::append_little_endian(buffer, p.x());
      detail::append_little_endian(buffer, p.y());
      detail::append_little_endian(buffer, p.z());
    } else {
      detail::append_point(buffer, p);
      buffer += '\n';
    }
    detail::flush_buffer(out, buffer);
  }
  for (const auto& triangle : mesh.triangles) {
    if (binary) {
      detail::append_little_endian(buffer, std::uint8_t{3});
      for (const Index v : triangle) {
        detail::append_little_endian(buffer, static_cast<std::int32_t>(v));
      }
    } else {
      buffer += "3 " + std::to_string(triangle[0]) + ' ' + std::to_string(triangle[1]) + ' ' +
                std::to_string(triangle[2]) + '\n';
    }
    detail::flush_buffer(out, buffer);
  }
  detail::flush_buffer(out, buffer, true);
}

}  // namespace

namespace detail {

void write_off(std::ostream& out, const TriangleMesh& mesh) {
  out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  std::string buffer;
  for (const Point3& p : mesh.vertices) {
    detail::append_point(buffer, p);
    buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  for (const auto& triangle : mesh.triangles) {
    buffer += "3 " + std::to_string(triangle[0]) + ' ' + std::to_string(triangle[1]) + ' ' +
              std::to_string(triangle[2]) + '\n';
    detail::flush_buffer(out, buffer);
  }
  detail::flush_buffer(out, buffer, true);
}

// Binary STL: an 80-byte header, the face count, then per face its unit normal (zero for a
// face without area), its three corners as float32 and a zero attribute word.
void write_stl(std::ostream& out, const TriangleMesh& mesh) {
  std::string header = "binary STL written by envcrust";
  header.resize(80, ' ');
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  std::string buffer;
  append_little_endian(buffer, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& triangle : mesh.triangles) {
    const Point3& a = mesh.vertices[triangle[0]];
    const Point3& b = mesh.vertices[triangle[1]];
    const Point3& c = mesh.vertices[triangle[2]];
    Vector3 n = CGAL::cross_product(b - a, c - a);
    const double length = std::sqrt(n.squared_length());
    n = length > 0 ? n / length : Vector3(0, 0, 0);
    for (const double v : {n.x(), n.y(), n.z()}) append_little_endian(buffer, static_cast<float>(v));
    for (const Point3* p : {&a, &b, &c})
      for (const double v : {p->x(), p->y(), p->z()}) append_little_endian(buffer, static_cast<float>(v));
    append_little_endian(buffer, std::uint16_t{0});
    flush_buffer(out, buffer);
  }
  flush_buffer(out, buffer, true);
}

}  // namespace detail

namespace {

void write_obj(std::ostream& out, const TriangleMesh& mesh) {
  out << "# written by envcrust\n";
  std::string buffer;
  for (const Point3& p : mesh.vertices) {
    buffer += "v ";
    detail::append_point(buffer, p);
    buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  for (const auto& triangle : mesh.triangles) {
    // OBJ counts vertices from 1.
    buffer += "f " + std::to_string(std::uint64_t{triangle[0]} + 1) + ' ' +
              std::to_string(std::uint64_t{triangle[1]} + 1) + ' ' +
              std::to_string(std::uint64_t{triangle[2]} + 1) + '\n';
    detail::flush_buffer(out, buffer);
  }
  detail::flush_buffer(out, buffer, true);
}

}  // namespace

void detail::check_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, bool int32_indices) {
  detail::check_finite(path, mesh.vertices, "vertex");
  if (int32_indices && mesh.vertices.size() > 0x7FFFFFFFu) {
    detail::fail(path, "cannot write " + std::to_string(mesh.vertices.size()) +
                           " vertices as PLY int indices");
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const Index v : mesh.triangles[t]) {
      if (v >= mesh.vertices.size()) {
        detail::fail(path, "cannot write triangle " + std::to_string(t) + ": vertex index " +
                               std::to_string(v) + " out of range (" +
                               std::to_string(mesh.vertices.size()) + " vertices)");
      }
    }
  }
}

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                PlyEncoding encoding) {
  using detail::check_mesh;
  const std::string extension = extension_of(path);
  if (extension == "ply") {
    check_mesh(path, mesh, true);
    write_atomic(path, encoding == PlyEncoding::Binary,
                 [&](std::ostream& out) { write_ply(out, mesh, encoding); });
  } else if (extension == "off") {
    check_mesh(path, mesh, false);
    write_atomic(path, false, [&](std::ostream& out) { detail::write_off(out, mesh); });
  } else if (extension == "obj") {
    check_mesh(path, mesh, false);
    write_atomic(path, false, [&](std::ostream& out) { write_obj(out, mesh); });
  } else if (extension == "stl") {
    check_mesh(path, mesh, true);  // STL counts faces in 32 bits
    write_atomic(path, true, [&](std::ostream& out) { detail::write_stl(out, mesh); });
  } else {
    detail::unknown_extension(path, ".ply, .off, .obj, .stl");
  }
}

}  // namespace envcrust::io
