// Reader of Wavefront OBJ meshes: `v` positions and `f` polygons (v, v/t, v//n, v/t/n, negative indices).
#include "io_detail.h"

#include <cmath>

namespace envcrust::io::detail {

namespace {

// The 0-based vertex of one `f` reference like "7", "7/2", "7//3", "-1/2/3".
Index parse_reference(const std::filesystem::path& path, std::size_t line, std::string_view token,
                      std::size_t vertex_count) {
  const std::string_view index_text = token.substr(0, token.find('/'));
  std::int64_t index = 0;
  if (!parse_int(index_text, index)) {
    fail_at(path, line, "expected a vertex index, got " + quote(token));
  }
  if (index == 0) {
    fail_at(path, line, "face index 0 is invalid (OBJ indices start at 1)");
  }
  // Negative indices count back from the last vertex defined so far.
  const std::int64_t resolved = index > 0 ? index - 1 : static_cast<std::int64_t>(vertex_count) + index;
  if (resolved < 0 || static_cast<std::uint64_t>(resolved) >= vertex_count) {
    fail_at(path, line,
            "face index " + std::to_string(index) + " out of range (" +
                std::to_string(vertex_count) + " vertices)");
  }
  return static_cast<Index>(resolved);
}

}  // namespace

RawMesh read_obj(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  RawMesh mesh;
  LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  while (lines.next(line)) {
    split_tokens(strip_comment(line), tokens);
    if (tokens.empty()) {
      continue;
    }
    const std::size_t number = lines.line_number();
    if (tokens[0] == "v") {
      if (tokens.size() < 4) {
        fail_at(path, number,
                "expected at least 3 numbers after 'v', got " + std::to_string(tokens.size() - 1));
      }
      if (mesh.vertices.size() >= max_vertices) {
        fail_at(path, number, "more than " + std::to_string(max_vertices) + " vertices");
      }
      double xyz[3] = {};
      for (int axis = 0; axis < 3; ++axis) {
        if (!parse_double(tokens[1 + axis], xyz[axis])) {
          fail_at(path, number, "expected a number, got " + quote(tokens[1 + axis]));
        }
        if (const char* problem = coordinate_problem(xyz[axis])) {
          fail_at(path, number, problem);
        }
      }
      mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) {
        fail_at(path, number,
                "face with " + std::to_string(tokens.size() - 1) + " vertices (need at least 3)");
      }
      std::vector<Index> face;
      face.reserve(tokens.size() - 1);
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        face.push_back(parse_reference(path, number, tokens[i], mesh.vertices.size()));
      }
      mesh.faces.push_back(std::move(face));
    }
    // Normals, texture coordinates, groups, materials, lines and points carry nothing we use.
  }
  return mesh;
}

}  // namespace envcrust::io::detail
