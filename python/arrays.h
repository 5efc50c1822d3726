// Conversions between numpy arrays and the library's points, faces and colours, with the
// shape and value checks that give a user a one-line ValueError instead of a crash.
#pragma once

#include "envcrust/attributes.h"
#include "envcrust/types.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace envcrust::python {

namespace py = pybind11;

/// The rows of an n x 3 array of finite numbers (any numeric dtype, or nested lists).
/// @throws py::value_error "points must be an array of shape (n, 3), got shape (5, 2)",
///   "points: row 7 has a non-finite coordinate".
std::vector<Point3> to_points(const py::handle& array, const char* what);

/// The same as vectors (normals): n x 3, finite.
std::vector<Vector3> to_vectors(const py::handle& array, const char* what);

/// Triangles of an m x 3 array of whole numbers, each an index below `vertex_count`.
/// @throws py::value_error "faces: row 3 has vertex index 12, out of range (10 vertices)".
std::vector<std::array<Index, 3>> to_triangles(const py::handle& array, std::size_t vertex_count);

/// Colours of an n x 3 array with `count` rows: whole numbers 0..255 (any integer dtype), or
/// floats in [0, 1] (scaled to 0..255), as mesh files store them.
/// @throws py::value_error "colors must have 100 rows (one per point), got 99", out-of-range values.
std::vector<Colour> to_colours(const py::handle& array, std::size_t count);

/// n x 3 float64 array of the points' coordinates.
py::array_t<double> points_array(const std::vector<Point3>& points);
/// n x 3 float64 array of vectors.
py::array_t<double> vectors_array(const std::vector<Vector3>& vectors);
/// m x 3 int64 array of vertex indices.
py::array_t<std::int64_t> triangles_array(const std::vector<std::array<Index, 3>>& triangles);
/// n x 3 uint8 array of colours.
py::array_t<std::uint8_t> colours_array(const std::vector<Colour>& colours);

}  // namespace envcrust::python
