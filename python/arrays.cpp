// Conversions between numpy arrays and the library's points, faces and colours.
#include "arrays.h"

#include <cmath>
#include <sstream>
#include <string>

namespace envcrust::python {
namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// An n x 3 array of float64 in C order (a copy when the input is another dtype or layout).
py::array_t<double, py::array::c_style | py::array::forcecast> rows_of_three(const py::handle& object,
                                                                          const char* what) {
  py::array any;
  try {
    any = py::array::ensure(object);
  } catch (const py::error_already_set&) {
  }
  if (!any) throw py::value_error(std::string(what) + " must be an array of shape (n, 3)");
  if (any.ndim() != 2 || any.shape(1) != 3)
    throw py::value_error(std::string(what) + " must be an array of shape (n, 3), got shape " + shape_text(any));
  if (any.dtype().kind() != 'f' && any.dtype().kind() != 'i' && any.dtype().kind() != 'u')
    throw py::value_error(std::string(what) + " must hold numbers, got dtype " + py::str(any.dtype()).cast<std::string>());
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(any);
}

template <class Row>
std::vector<Row> finite_rows(const py::handle& object, const char* what) {
  const auto a = rows_of_three(object, what);
  const auto r = a.unchecked<2>();
  std::vector<Row> rows;
  rows.reserve(r.shape(0));
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    if (!std::isfinite(r(i, 0)) || !std::isfinite(r(i, 1)) || !std::isfinite(r(i, 2)))
      throw py::value_error(std::string(what) + ": row " + std::to_string(i) + " has a non-finite coordinate");
    rows.emplace_back(r(i, 0), r(i, 1), r(i, 2));
  }
  return rows;
}

template <class T>
py::array_t<T> array_of_rows(std::size_t rows) {
  return py::array_t<T>({static_cast<py::ssize_t>(rows), py::ssize_t{3}});
}

}  // namespace

std::vector<Point3> to_points(const py::handle& array, const char* what) { return finite_rows<Point3>(array, what); }

std::vector<Vector3> to_vectors(const py::handle& array, const char* what) {
  return finite_rows<Vector3>(array, what);
}

std::vector<std::array<Index, 3>> to_triangles(const py::handle& array, std::size_t vertex_count) {
  const auto a = rows_of_three(array, "faces");
  const auto r = a.unchecked<2>();
  std::vector<std::array<Index, 3>> triangles(r.shape(0));
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    for (int c = 0; c < 3; ++c) {
      const double v = r(i, c);
      if (!(v >= 0 && v < static_cast<double>(vertex_count)) || v != std::floor(v)) {
        std::ostringstream text;
        text << "faces: row " << i << " has vertex index " << v << ", out of range (" << vertex_count << " vertices)";
        throw py::value_error(text.str());
      }
      triangles[i][c] = static_cast<Index>(v);
    }
  return triangles;
}

std::vector<Colour> to_colours(const py::handle& array, std::size_t count) {
  const bool is_float = py::array::ensure(array) && py::array::ensure(array).dtype().kind() == 'f';
  const auto a = rows_of_three(array, "colors");
  const auto r = a.unchecked<2>();
  if (static_cast<std::size_t>(r.shape(0)) != count)
    throw py::value_error("colors must have " + std::to_string(count) + " rows (one per point), got " +
                          std::to_string(r.shape(0)));
  const double top = is_float ? 1.0 : 255.0;
  std::vector<Colour> colours(count);
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    for (int c = 0; c < 3; ++c) {
      const double v = r(i, c);
      if (!(v >= 0 && v <= top))
        throw py::value_error("colors: row " + std::to_string(i) + " has a value outside " +
                              (is_float ? "[0, 1] (float colours)" : "0..255 (integer colours)"));
      colours[i][c] = static_cast<std::uint8_t>(std::lround(v * 255.0 / top));
    }
  return colours;
}

py::array_t<double> points_array(const std::vector<Point3>& points) {
  auto out = array_of_rows<double>(points.size());
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int c = 0; c < 3; ++c) w(i, c) = points[i][c];
  return out;
}

py::array_t<double> vectors_array(const std::vector<Vector3>& vectors) {
  auto out = array_of_rows<double>(vectors.size());
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < vectors.size(); ++i)
    for (int c = 0; c < 3; ++c) w(i, c) = vectors[i][c];
  return out;
}

py::array_t<std::int64_t> triangles_array(const std::vector<std::array<Index, 3>>& triangles) {
  auto out = array_of_rows<std::int64_t>(triangles.size());
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int c = 0; c < 3; ++c) w(i, c) = triangles[i][c];
  return out;
}

py::array_t<std::uint8_t> colours_array(const std::vector<Colour>& colours) {
  auto out = array_of_rows<std::uint8_t>(colours.size());
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < colours.size(); ++i)
    for (int c = 0; c < 3; ++c) w(i, c) = colours[i][c];
  return out;
}

}  // namespace envcrust::python
