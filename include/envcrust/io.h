// File formats at the edge of the library: reading and writing point sets and meshes.
#pragma once

#include "envcrust/attributes.h"
#include "envcrust/image.h"
#include "envcrust/nurbs_surface.h"
#include "envcrust/types.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace envcrust::io {

/// Read a point set, format chosen by extension (case-insensitive):
///  - `.xyz/.pts/.txt/.csv`: fields separated by white space or commas; `#` comments and
///    blank lines allowed. Every data line has the first's column count. Without a header
///    line: x y z, then 4 columns x y z intensity, 6 x y z nx ny nz, 7 x y z intensity r g b,
///    9 x y z nx ny nz r g b (or x y z r g b nx ny nz: the triple of whole numbers 0..255 is
///    the colour), any other count x y z and scalars column_4, column_5, ... Under a first
///    line that names the columns: x, y, z required; nx, ny, nz and r, g, b (or red, green,
///    blue) read when all three are named; every other column a scalar of its name (dropped
///    if some value in it is not a number). `.pts` also skips Leica's point-count lines.
///  - `.ply`: ascii or binary (little/big endian), vertex x,y,z and optional nx,ny,nz;
///    red, green, blue (integer 0..255, 16-bit scaled down, float 0..1) as colours; every
///    other non-list vertex property (alpha, intensity, ...) a scalar of its name.
///  - `.off/.obj/.stl`: the vertices of the mesh (normals: none; `.obj` colours "v x y z r g b",
///    0..1 or 0..255, when every vertex has one).
///  - `.las`: LAS 1.0 to 1.4, point data formats 0 to 10 (extra bytes per record skipped):
///    X, Y, Z times the header's scale plus its offset, in double; RGB of formats 2, 3, 5, 7, 8
///    and 10 as colours (16-bit scaled down, unless every value is within 0..255: then 8-bit);
///    the scalars "intensity" and "classification" (the class number, 0..31 for formats 0 to 5).
///    Compressed files (`.laz`, or the format id's compression bit) are refused, naming laszip
///    and pdal as ways to decompress them.
/// @throws IoError one line naming the file and the problem, e.g.
///   "scan.xyz:12: expected at least 3 numbers ..., got 2", "scan.ply: truncated binary data
///   (vertex 17 of 100)", "a.xyz:3: non-finite coordinate", "a.xyz: no points", "a.las: truncated
///   point data: the header announces 1000 points of 26 bytes, the file holds 500".
AttributedPoints read_attributed_points(const std::filesystem::path& path);

/// read_attributed_points without the attributes.
PointSet read_points(const std::filesystem::path& path);

/// Read the NURBS patches of a file, format chosen by extension: `.igs/.iges` (IGES: every
/// rational B-spline surface, entity 128, placed by its transformation matrix if any, and
/// every trimmed surface over one, entity 144, in the order of the directory; bounded
/// surfaces, 143, are refused) or `.json` (NURBS-Python's exchange format: a "shape" of type
/// "surface" with one or more entries, control points listed v fastest, weights optional).
/// The patches are checked by surfaces::make_nurbs_surface and joined by models::PatchModel,
/// not here.
/// @throws IoError one line naming the file and the problem, e.g. "a.igs: a bounded surface
///   (IGES entity 143): not supported; ...", "a.json: surface 2: size_u is 0, not a count of 1 to 1000000".
std::vector<surfaces::NurbsPatch> read_nurbs_patches(const std::filesystem::path& path);

/// True for the extensions read_nurbs_patches reads (.igs, .iges, .json).
bool is_nurbs_file(const std::filesystem::path& path);

/// Read a polygon mesh from `.off/.obj/.ply/.stl` (STL ascii or binary; its duplicated
/// corners are merged by exact position). Faces must have >= 3 valid vertex indices.
/// @throws IoError as read_points, plus "m.off:7: face index 12 out of range (10 vertices)".
PolygonMesh read_polygon_mesh(const std::filesystem::path& path);

/// Read a mesh and fan-triangulate its polygons (polygons are assumed convex-ish).
TriangleMesh read_triangle_mesh(const std::filesystem::path& path);

/// Read an ordered closed curve: `.polyline` (one point per line, or the CGAL polyline
/// format "n x1 y1 z1 ... xn yn zn" on one line) or `.xyz/.txt/.pts/.csv` (one point per line,
/// read as read_points reads them).
/// A last point equal to the first is dropped. @throws IoError (fewer than 3 points, ...).
Polyline read_polyline(const std::filesystem::path& path);

/// Encoding of written PLY files.
enum class PlyEncoding { Binary, Ascii };

/// Write a triangle mesh; format by extension: `.ply` (binary by default, double x, y, z),
/// `.off`, `.obj`, `.stl` (binary).
/// Written atomically (temp file in the same folder, then rename).
/// @throws IoError on unknown extension or a failed write.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                PlyEncoding encoding = PlyEncoding::Binary);

/// What a mesh file holds per vertex besides its position (write_mesh with vertex data).
struct MeshVertexData {
  std::vector<Vector3> normals;  ///< empty or one per vertex
  PointAttributes attributes;    ///< colours and scalars: empty or one per vertex
};

/// Write a triangle mesh with per-vertex data; format by extension:
///  - `.ply`: float32 x, y, z (float64 where float32 would round a coordinate by more than
///    1e-6 of the mesh's diagonal: far from the origin for its size, as georeferenced scans
///    are), float nx, ny, nz, uchar red, green, blue and a float property per scalar;
///  - `.obj`: `vn` normals, colours as "v x y z r g b" (0..1, as MeshLab writes); no scalars;
///  - `.off`: positions only; `.stl` (binary): each face with its normal, no vertex data.
/// Written atomically. @throws IoError on unknown extension, data of the wrong size or a failed write.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, const MeshVertexData& data,
                PlyEncoding encoding = PlyEncoding::Binary);

/// Write a point set (with normals if present): `.xyz` (ascii) or `.ply` (binary by default).
void write_points(const std::filesystem::path& path, const PointSet& points,
                  PlyEncoding encoding = PlyEncoding::Binary);

/// Write a closed polyline as `.polyline` / `.xyz` (one point per line).
void write_polyline(const std::filesystem::path& path, const Polyline& curve);

/// Write a file atomically: `fill` writes into a stream opened on a temp file next to `path`;
/// on success the temp file is renamed onto `path`; on any failure it is removed and no
/// partial output remains. A symbolic link is followed (its target is replaced, the link
/// stays); an existing device, pipe or socket is refused, not replaced.
/// @throws IoError naming the file.
void write_atomic(const std::filesystem::path& path, bool binary,
                  const std::function<void(std::ostream&)>& fill);

/// Write a text file atomically (reports, JSON).
void write_text(const std::filesystem::path& path, const std::string& text);

/// Removes the temporary files write_atomic is filling at the moment. Async-signal-safe:
/// for a SIGINT/SIGTERM handler, so that an interrupted run leaves no hidden .tmp file.
void remove_pending_temp_files() noexcept;

/// What an output file is written as, for check_output_path.
enum class OutputKind {
  Mesh,    ///< write_mesh: .ply, .off, .obj, .stl
  Points,  ///< write_points: .xyz, .ply
  Image,     ///< write_png: .png
  Polyline,  ///< write_polyline: .polyline, .xyz
  Text       ///< write_text: any name
};

/// Check before a long run that `path` can be written as `kind`: a file name with a known
/// extension, in a folder that exists and is writable, not itself a folder ("out: is a
/// folder, not a file") nor a device, pipe or socket.
/// @throws IoError naming the file ("x.unknown: unknown
/// extension '.unknown' (expected .ply, .off, .obj, .stl)", "out/x.ply: folder 'out' does not exist").
void check_output_path(const std::filesystem::path& path, OutputKind kind);

/// Balls (e.g. the polar balls of the Power Crust): centre, radius and an optional label.
struct BallSet {
  std::vector<Point3> centres;
  std::vector<double> radii;        ///< one per centre, > 0
  std::vector<std::string> labels;  ///< one per centre; "" when the line has none
};

/// Read balls (what `envcrust powercrust --poles` writes): `.ply` vertices with x, y, z,
/// `radius` and an optional `label` code (0 unknown, 1 in, 2 out); any other extension is text,
/// one ball per line "x y z radius [label]", `#` comments and blank lines allowed.
/// @throws IoError e.g. "poles.txt:4: expected x y z radius [label], got 3 values",
///   "poles.txt:4: radius must be finite and > 0 (got -1)", "poles.txt: no balls",
///   "p.ply: PLY vertices have no 'radius' property".
BallSet read_balls(const std::filesystem::path& path);

/// Write balls atomically: `.ply` as binary PLY (x, y, z, radius as double, uchar label code:
/// labels must be "", unknown, in or out), any other extension as text read_balls reads.
/// @throws IoError naming the file (non-finite centre, radius <= 0, unknown label, write failure).
void write_balls(const std::filesystem::path& path, const BallSet& balls);

/// The whole file as bytes (fonts, ...). @throws IoError "FILE: cannot open file" and friends.
std::vector<std::uint8_t> read_binary_file(const std::filesystem::path& path);

/// Write an RGB image as an 8-bit PNG, atomically. The bytes depend only on the pixels (no
/// time stamp). @throws IoError naming the file on a bad image size or a failed write.
void write_png(const std::filesystem::path& path, const render::Image& image);

/// Read a PNG as 8-bit RGB (any colour type; alpha composed over black, 16-bit reduced).
/// @throws IoError "FILE: not a PNG file (...)" and friends.
render::Image read_png(const std::filesystem::path& path);

/// Lower-case extension without the dot ("ply", "xyz"); "" when none.
std::string extension_of(const std::filesystem::path& path);

/// Whether the file's extension is one of the plain-text point formats (.xyz/.pts/.txt/.csv).
bool is_text_point_file(const std::filesystem::path& path);

}  // namespace envcrust::io
