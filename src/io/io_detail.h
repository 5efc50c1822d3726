// Private helpers shared by the io readers and writers: error formatting, file slurping, number parsing.
#pragma once

#include "envcrust/attributes.h"
#include "envcrust/errors.h"
#include "envcrust/nurbs_surface.h"
#include "envcrust/types.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstring>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace envcrust::io::detail {

/// Throw IoError "FILE: problem".
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem);

/// Coordinates beyond this magnitude are refused: their squares and cross products (areas,
/// volumes, distances) would overflow a double in the stages that follow.
inline constexpr double max_coordinate = 1e30;

/// What is wrong with a coordinate read from a file: "non-finite coordinate", "coordinate
/// beyond 1e30 in magnitude", or nullptr when it is usable.
inline const char* coordinate_problem(double value) {
  if (!std::isfinite(value)) return "non-finite coordinate";
  if (std::abs(value) > max_coordinate) return "coordinate beyond 1e30 in magnitude: scale the input down";
  return nullptr;
}

/// Throw IoError "FILE:LINE: problem".
[[noreturn]] void fail_at(const std::filesystem::path& path, std::size_t line,
                          const std::string& problem);

/// Throw IoError "FILE: unknown extension '.foo' (expected LIST)" (or "no extension").
[[noreturn]] void unknown_extension(const std::filesystem::path& path, const char* expected);

/// The whole file as bytes. @throws IoError "FILE: cannot open file" and friends.
std::string read_file(const std::filesystem::path& path);

/// Parse a whole token as a double (accepts a leading '+', "nan", "inf").
bool parse_double(std::string_view token, double& value);

/// Parse a whole token as a signed integer.
bool parse_int(std::string_view token, std::int64_t& value);

/// Append the whitespace-separated tokens of `line` to `tokens` (after clearing it).
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens);
/// The fields of a point or curve file's line: separated by commas when it has any (each
/// comma ends one, so "1,,2" has an empty field; spaces around fields trimmed), else by white
/// space (split_tokens).
void split_fields(std::string_view line, std::vector<std::string_view>& tokens);

/// `line` without anything from the first `#` on.
std::string_view strip_comment(std::string_view line);

/// Shortest decimal text that reads back to exactly `value`.
void append_double(std::string& out, double value);

/// Append "x y z" with append_double.
void append_point(std::string& out, const Point3& p);

/// Write `buffer` to `out` and clear it once it is large (always when `force`).
void flush_buffer(std::ostream& out, std::string& buffer, bool force = false);

/// Walks a text buffer line by line, counting lines from 1 and dropping a trailing '\r' (and,
/// from a whole file, the UTF-8 byte-order mark that spreadsheet exports put first).
class LineCursor {
 public:
  explicit LineCursor(std::string_view text, std::size_t first_line = 1)
      : text_(text), pos_(first_line == 1 && text.starts_with("\xEF\xBB\xBF") ? 3 : 0), next_line_(first_line) {}
  /// Next line into `line`; false at the end of the text.
  bool next(std::string_view& line);
  /// Number of the line returned by the last next().
  [[nodiscard]] std::size_t line_number() const { return next_line_ - 1; }
  /// Bytes not yet consumed.
  [[nodiscard]] std::size_t remaining() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t next_line_;
};

/// Walks a text buffer token by token across lines, remembering each token's line.
class TokenCursor {
 public:
  explicit TokenCursor(std::string_view text, std::size_t first_line = 1)
      : text_(text), line_(first_line) {}
  /// Next token into `token`; false at the end of the text.
  bool next(std::string_view& token);
  /// Line of the token returned by the last next() (or of the end, after it failed).
  [[nodiscard]] std::size_t line_number() const { return token_line_; }
  /// Bytes not yet consumed.
  [[nodiscard]] std::size_t remaining() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
  std::size_t token_line_ = 0;
};

/// A mesh or point cloud as it comes out of a reader, before the public type is chosen.
struct RawMesh {
  std::vector<Point3> vertices;
  std::vector<Vector3> normals;  ///< empty or one per vertex
  std::vector<std::vector<Index>> faces;
  std::vector<double> radii;   ///< PLY vertex property `radius`: empty or one per vertex
  std::vector<double> labels;  ///< PLY vertex property `label`: empty or one per vertex
  PointAttributes attributes;  ///< PLY vertex colours and other scalar properties
};

RawMesh read_ply(const std::filesystem::path& path);
RawMesh read_off(const std::filesystem::path& path);
RawMesh read_obj(const std::filesystem::path& path);
RawMesh read_stl(const std::filesystem::path& path);
AttributedPoints read_xyz(const std::filesystem::path& path);
/// A LAS point cloud (.las; a .laz file, or a LAS file marked compressed, is refused).
AttributedPoints read_las(const std::filesystem::path& path);
/// The rational B-spline surfaces of an IGES file, trimmed or not (read_nurbs_patches).
std::vector<surfaces::NurbsPatch> read_iges_patches(const std::filesystem::path& path);

/// Text for quoting a token in a message, shortened when it is long.
std::string quote(std::string_view token);

/// Append `value` to `out` as little-endian bytes (the byte order of the PLY files we write).
template <class T>
void append_little_endian(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    std::reverse(bytes, bytes + sizeof(T));
  }
  out.append(bytes, sizeof(T));
}

/// Throw IoError unless every coordinate is finite (a written NaN could not be read back).
void check_finite(const std::filesystem::path& path, const std::vector<Point3>& points,
                  const char* what);

/// Throw IoError unless the mesh can be written: finite vertices, triangles' indices in
/// range, and (`int32_indices`) at most 2^31 - 1 vertices.
void check_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, bool int32_indices);

/// The mesh as OFF text (positions and faces).
void write_off(std::ostream& out, const TriangleMesh& mesh);

/// The mesh as binary STL (each face with its normal; STL holds no vertex data).
void write_stl(std::ostream& out, const TriangleMesh& mesh);

/// Largest vertex count an Index can address.
inline constexpr std::uint64_t max_vertices = 0xFFFFFFFFull;

}  // namespace envcrust::io::detail
