// Reader of OFF meshes (plain OFF, plus the COFF/NOFF/CNOFF variants whose extra columns are ignored).
#include "io_detail.h"

#include <algorithm>
#include <cmath>

namespace envcrust::io::detail {

namespace {

// Next line with data, comments removed; false at the end of the file.
bool next_data_line(LineCursor& lines, std::vector<std::string_view>& tokens) {
  std::string_view line;
  while (lines.next(line)) {
    split_tokens(strip_comment(line), tokens);
    if (!tokens.empty()) {
      return true;
    }
  }
  return false;
}

std::uint64_t parse_count(const std::filesystem::path& path, std::size_t line,
                          std::string_view token) {
  std::int64_t value = 0;
  if (!parse_int(token, value) || value < 0) {
    fail_at(path, line, "expected counts 'VERTICES FACES [EDGES]', got " + quote(token));
  }
  return static_cast<std::uint64_t>(value);
}

struct Variant {
  std::size_t min_columns = 3;
  std::size_t max_columns = 3;
};

// The header keyword's variant; refuses the ones whose vertex lines we cannot read.
Variant parse_keyword(const std::filesystem::path& path, std::size_t line,
                      std::string_view keyword) {
  if (keyword == "OFF") {
    return {3, 3};
  }
  if (keyword == "COFF") {
    return {3, 7};  // colour as 1 index or 3-4 components
  }
  if (keyword == "NOFF") {
    return {6, 6};
  }
  if (keyword == "CNOFF" || keyword == "NCOFF") {
    return {6, 10};
  }
  if (keyword.size() > 3 && keyword.substr(keyword.size() - 3) == "OFF") {
    fail_at(path, line,
            "unsupported OFF variant " + quote(keyword) + " (supported: OFF, COFF, NOFF, CNOFF)");
  }
  fail_at(path, line, "expected 'OFF', got " + quote(keyword));
}

}  // namespace

RawMesh read_off(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  LineCursor lines(data);
  std::vector<std::string_view> tokens;
  if (!next_data_line(lines, tokens)) {
    fail(path, "empty file (expected an OFF header)");
  }
  Variant variant;
  std::size_t first_count = 0;
  std::int64_t ignored = 0;
  const bool has_keyword = !parse_int(tokens[0], ignored);  // the keyword is optional
  if (has_keyword) {
    variant = parse_keyword(path, lines.line_number(), tokens[0]);
    if (tokens.size() > 1 && tokens[1] == "BINARY") {
      fail_at(path, lines.line_number(), "binary OFF is not supported");
    }
    if (tokens.size() > 1) {
      first_count = 1;  // "OFF 8 6 0" on one line
    } else if (!next_data_line(lines, tokens)) {
      fail(path, "unexpected end of file (expected counts 'VERTICES FACES [EDGES]')");
    }
  }
  const std::size_t counts_line = lines.line_number();
  const std::size_t count_tokens = tokens.size() - first_count;
  if (count_tokens != 2 && count_tokens != 3) {
    fail_at(path, counts_line, "expected counts 'VERTICES FACES [EDGES]'");
  }
  const std::uint64_t vertex_count = parse_count(path, counts_line, tokens[first_count]);
  const std::uint64_t face_count = parse_count(path, counts_line, tokens[first_count + 1]);
  if (count_tokens == 3) {
    parse_count(path, counts_line, tokens[first_count + 2]);
  }
  if (vertex_count > max_vertices) {
    fail_at(path, counts_line,
            std::to_string(vertex_count) + " vertices exceed the limit of " +
                std::to_string(max_vertices));
  }

  RawMesh mesh;
  // Counts come from the file: reserve no more than its remaining lines can hold.
  mesh.vertices.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(vertex_count, lines.remaining() / 6)));
  for (std::uint64_t v = 0; v < vertex_count; ++v) {
    if (!next_data_line(lines, tokens)) {
      fail(path, "unexpected end of file (vertex " + std::to_string(v) + " of " +
                     std::to_string(vertex_count) + ")");
    }
    const std::size_t line = lines.line_number();
    if (tokens.size() < variant.min_columns || tokens.size() > variant.max_columns) {
      const std::string expected =
          variant.min_columns == variant.max_columns
              ? std::to_string(variant.min_columns)
              : std::to_string(variant.min_columns) + " to " + std::to_string(variant.max_columns);
      fail_at(path, line,
              "expected " + expected + " numbers for vertex " + std::to_string(v) + ", got " +
                  std::to_string(tokens.size()));
    }
    double xyz[3] = {};
    for (int axis = 0; axis < 3; ++axis) {
      if (!parse_double(tokens[axis], xyz[axis])) {
        fail_at(path, line, "expected a number, got " + quote(tokens[axis]));
      }
      if (const char* problem = coordinate_problem(xyz[axis])) {
        fail_at(path, line, problem);
      }
    }
    mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  mesh.faces.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(face_count, lines.remaining() / 8)));
  for (std::uint64_t f = 0; f < face_count; ++f) {
    if (!next_data_line(lines, tokens)) {
      fail(path, "unexpected end of file (face " + std::to_string(f) + " of " +
                     std::to_string(face_count) + ")");
    }
    const std::size_t line = lines.line_number();
    std::int64_t size = 0;
    if (!parse_int(tokens[0], size)) {
      fail_at(path, line, "expected a face size, got " + quote(tokens[0]));
    }
    if (size < 3) {
      fail_at(path, line, "face with " + std::to_string(size) + " vertices (need at least 3)");
    }
    if (static_cast<std::uint64_t>(size) > tokens.size() - 1) {
      fail_at(path, line,
              "face of size " + std::to_string(size) + " lists " +
                  std::to_string(tokens.size() - 1) + " indices");
    }
    std::vector<Index> face;
    face.reserve(static_cast<std::size_t>(size));
    for (std::int64_t i = 1; i <= size; ++i) {
      std::int64_t index = 0;
      if (!parse_int(tokens[static_cast<std::size_t>(i)], index)) {
        fail_at(path, line, "expected a vertex index, got " + quote(tokens[static_cast<std::size_t>(i)]));
      }
      if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count) {
        fail_at(path, line,
                "face index " + std::to_string(index) + " out of range (" +
                    std::to_string(vertex_count) + " vertices)");
      }
      face.push_back(static_cast<Index>(index));
    }
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

}  // namespace envcrust::io::detail
