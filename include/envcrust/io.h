// File formats at the edge of the library: reading and writing point sets and meshes.
#pragma once

#include "envcrust/types.h"

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>

namespace envcrust::io {

/// Read a point set, format chosen by extension (case-insensitive):
///  - `.xyz/.pts/.txt`: 3 or 6 numbers per line (position, optional normal); `#` comments and
///    blank lines allowed; every data line must have the same column count as the first.
///  - `.ply`: ascii or binary (little/big endian), vertex x,y,z and optional nx,ny,nz.
///  - `.off/.obj/.stl`: the vertices of the mesh (normals: none).
/// @throws IoError one line naming the file and the problem, e.g.
///   "scan.xyz:12: expected 3 or 6 numbers, got 2", "scan.ply: truncated binary data
///   (vertex 17 of 100)", "a.xyz:3: non-finite coordinate", "a.xyz: no points".
PointSet read_points(const std::filesystem::path& path);

/// Read a polygon mesh from `.off/.obj/.ply/.stl` (STL ascii or binary; its duplicated
/// corners are merged by exact position). Faces must have >= 3 valid vertex indices.
/// @throws IoError as read_points, plus "m.off:7: face index 12 out of range (10 vertices)".
PolygonMesh read_polygon_mesh(const std::filesystem::path& path);

/// Read a mesh and fan-triangulate its polygons (polygons are assumed convex-ish).
TriangleMesh read_triangle_mesh(const std::filesystem::path& path);

/// Read an ordered closed curve: `.polyline` (one point per line, or the CGAL polyline
/// format "n x1 y1 z1 ... xn yn zn" on one line) or `.xyz/.txt/.pts` (one point per line).
/// A last point equal to the first is dropped. @throws IoError (fewer than 3 points, ...).
Polyline read_polyline(const std::filesystem::path& path);

/// Encoding of written PLY files.
enum class PlyEncoding { Binary, Ascii };

/// Write a triangle mesh; format by extension: `.ply` (binary by default), `.off`, `.obj`.
/// Written atomically (temp file in the same folder, then rename).
/// @throws IoError on unknown extension or a failed write.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                PlyEncoding encoding = PlyEncoding::Binary);

/// Write a point set (with normals if present): `.xyz` (ascii) or `.ply` (binary by default).
void write_points(const std::filesystem::path& path, const PointSet& points,
                  PlyEncoding encoding = PlyEncoding::Binary);

/// Write a closed polyline as `.polyline` / `.xyz` (one point per line).
void write_polyline(const std::filesystem::path& path, const Polyline& curve);

/// Write a file atomically: `fill` writes into a stream opened on a temp file next to `path`;
/// on success the temp file is renamed onto `path`; on any failure it is removed and no
/// partial output remains. @throws IoError naming the file.
void write_atomic(const std::filesystem::path& path, bool binary,
                  const std::function<void(std::ostream&)>& fill);

/// Write a text file atomically (reports, JSON).
void write_text(const std::filesystem::path& path, const std::string& text);

/// Lower-case extension without the dot ("ply", "xyz"); "" when none.
std::string extension_of(const std::filesystem::path& path);

}  // namespace envcrust::io
