// Reader of Wavefront OBJ meshes: `v` positions (with vertex colours, "v x y z r g b", as MeshLab
// writes them) and `f` polygons (v, v/t, v//n, v/t/n, negative indices).
#include "io_detail.h"

#include <algorithm>
#include <array>
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

// "v x y z r g b" colours as 0..255: fractions of 1 as MeshLab writes them, or 0..255 when some
// value is above 1. Kept only when every vertex has one.
void add_vertex_colours(const std::vector<std::array<double, 3>>& colours, std::size_t vertices,
                        PointAttributes& attributes) {
  if (colours.empty() || colours.size() != vertices) return;
  bool fractions = true;
  for (const auto& c : colours)
    for (const double v : c) fractions = fractions && v <= 1;
  const double scale = fractions ? 255.0 : 1.0;
  for (const auto& c : colours) {
    Colour colour{};
    for (std::size_t k = 0; k < 3; ++k) {
      const double v = c[k] * scale;
      colour[k] = v > 0 ? static_cast<std::uint8_t>(std::lround(std::min(v, 255.0))) : 0;
    }
    attributes.colours.push_back(colour);
  }
}

}  // namespace

RawMesh read_obj(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  RawMesh mesh;
  LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  std::vector<std::array<double, 3>> colours;
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
      std::array<double, 3> rgb{};
      if (tokens.size() == 7 && parse_double(tokens[4], rgb[0]) && parse_double(tokens[5], rgb[1]) &&
          parse_double(tokens[6], rgb[2]) && colours.size() + 1 == mesh.vertices.size())
        colours.push_back(rgb);
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
  add_vertex_colours(colours, mesh.vertices.size(), mesh.attributes);
  return mesh;
}

}  // namespace envcrust::io::detail
