// Writers of point sets (with their normals when present) as .xyz text or PLY.
#include "envcrust/io.h"

#include "io_detail.h"

#include <ostream>

namespace envcrust::io {

namespace {

void append_vector(std::string& buffer, const Vector3& v) {
  detail::append_double(buffer, v.x());
  buffer += ' ';
  detail::append_double(buffer, v.y());
  buffer += ' ';
  detail::append_double(buffer, v.z());
}

void write_xyz(std::ostream& out, const PointSet& points) {
  std::string buffer;
  for (std::size_t i = 0; i < points.size(); ++i) {
    detail::append_point(buffer, points.points[i]);
    if (points.has_normals()) {
      buffer += ' ';
      append_vector(buffer, points.normals[i]);
    }
    buffer += '\n';
    detail::flush_buffer(out, buffer);
  }
  detail::flush_buffer(out, buffer, true);
}

void write_ply(std::ostream& out, const PointSet& points, PlyEncoding encoding) {
  const bool binary = encoding == PlyEncoding::Binary;
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment written by envcrust\n"
      << "element vertex " << points.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\n";
  if (points.has_normals()) {
    out << "property double nx\nproperty double ny\nproperty double nz\n";
  }
  out << "end_header\n";
  std::string buffer;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points.points[i];
    if (binary) {
      detail::append_little_endian(buffer, p.x());
      detail::append_little_endian(buffer, p.y());
      detail::append_little_endian(buffer, p.z());
      if (points.has_normals()) {
        const Vector3& n = points.normals[i];
        detail::append_little_endian(buffer, n.x());
        detail::append_little_endian(buffer, n.y());
        detail::append_little_endian(buffer, n.z());
      }
    } else {
      detail::append_point(buffer, p);
      if (points.has_normals()) {
        buffer += ' ';
        append_vector(buffer, points.normals[i]);
      }
      buffer += '\n';
    }
    detail::flush_buffer(out, buffer);
  }
  detail::flush_buffer(out, buffer, true);
}

void check_points(const std::filesystem::path& path, const PointSet& points) {
  if (points.has_normals() && points.normals.size() != points.points.size()) {
    detail::fail(path, "cannot write " + std::to_string(points.normals.size()) + " normals for " +
                           std::to_string(points.points.size()) + " points");
  }
  detail::check_finite(path, points.points, "point");
  for (std::size_t i = 0; i < points.normals.size(); ++i) {
    const Vector3& n = points.normals[i];
    if (!std::isfinite(n.x()) || !std::isfinite(n.y()) || !std::isfinite(n.z())) {
      detail::fail(path, "cannot write non-finite normal (point " + std::to_string(i) + ")");
    }
  }
}

}  // namespace

void write_points(const std::filesystem::path& path, const PointSet& points,
                  PlyEncoding encoding) {
  const std::string extension = extension_of(path);
  if (extension == "xyz") {
    check_points(path, points);
    write_atomic(path, false, [&](std::ostream& out) { write_xyz(out, points); });
  } else if (extension == "ply") {
    check_points(path, points);
    write_atomic(path, encoding == PlyEncoding::Binary,
                 [&](std::ostream& out) { write_ply(out, points, encoding); });
  } else {
    detail::unknown_extension(path, ".xyz, .ply");
  }
}

}  // namespace envcrust::io
