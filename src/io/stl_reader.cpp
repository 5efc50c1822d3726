// Reader of STL meshes (ascii and binary), merging the corners STL repeats per triangle.
#include "io_detail.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace envcrust::io::detail {

namespace {

constexpr std::size_t binary_header_size = 84;
constexpr std::size_t binary_triangle_size = 50;

std::uint32_t read_le_u32(const char* bytes) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) {
    value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  }
  return value;
}

float read_le_float(const char* bytes) {
  const std::uint32_t bits = read_le_u32(bytes);
  float value = 0.0F;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// Gives each distinct position one vertex index; -0.0 and 0.0 are the same position.
class VertexMerger {
 public:
  explicit VertexMerger(RawMesh& mesh) : mesh_(mesh) {}
  Index add(double x, double y, double z) {
    const Key key{x + 0.0, y + 0.0, z + 0.0};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<Index>(mesh_.vertices.size()));
    if (inserted) {
      mesh_.vertices.emplace_back(x, y, z);
    }
    return it->second;
  }

 private:
  using Key = std::array<double, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      std::size_t seed = 0;
      for (double c : key) {
        seed ^= std::hash<double>{}(c) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
      }
      return seed;
    }
  };
  RawMesh& mesh_;
  std::unordered_map<Key, Index, KeyHash> index_;
};

bool looks_ascii(std::string_view data) {
  const auto start = data.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || data.substr(start, 5) != "solid") {
    return false;
  }
  // Binary headers may start with "solid" too, but their counts and floats contain zero bytes.
  const std::string_view head = data.substr(0, 1024);
  return head.find('\0') == std::string_view::npos;
}

RawMesh read_binary(const std::filesystem::path& path, std::string_view data) {
  if (data.size() < binary_header_size) {
    fail(path, "truncated binary data (" + std::to_string(data.size()) +
                   "-byte file, a binary STL header has 84 bytes)");
  }
  const std::uint32_t count = read_le_u32(data.data() + 80);
  const std::size_t available = (data.size() - binary_header_size) / binary_triangle_size;
  if (available < count) {
    fail(path, "truncated binary data (triangle " + std::to_string(available) + " of " +
                   std::to_string(count) + ")");
  }
  RawMesh mesh;
  mesh.faces.reserve(count);
  VertexMerger merger(mesh);
  for (std::uint32_t t = 0; t < count; ++t) {
    // Skip the facet normal: it is redundant and often wrong in files found in the wild.
    const char* corner = data.data() + binary_header_size + t * binary_triangle_size + 12;
    std::vector<Index> face(3);
    for (int c = 0; c < 3; ++c) {
      double xyz[3];
      for (int axis = 0; axis < 3; ++axis) {
        xyz[axis] = read_le_float(corner + 4 * (3 * c + axis));
        if (const char* problem = coordinate_problem(xyz[axis])) {
          fail(path, "triangle " + std::to_string(t) + ": " + problem);
        }
      }
      face[c] = merger.add(xyz[0], xyz[1], xyz[2]);
    }
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

class AsciiParser {
 public:
  AsciiParser(const std::filesystem::path& path, std::string_view data)
      : path_(path), tokens_(data) {}

  RawMesh parse() {
    RawMesh mesh;
    VertexMerger merger(mesh);
    std::string_view token;
    next(token);  // "solid", checked by looks_ascii
    skip_name(token);
    while (!token.empty()) {
      if (token == "endsolid") {
        // Several solids may follow each other; their names are free text.
        while (tokens_.next(token) && token != "solid") {
        }
        if (token != "solid") {
          break;
        }
        skip_name(token);
        continue;
      }
      if (token != "facet") {
        error("expected 'facet' or 'endsolid', got " + quote(token));
      }
      expect("normal");
      for (int i = 0; i < 3; ++i) {
        next(token);  // facet normals are not used
      }
      expect("outer");
      expect("loop");
      std::vector<Index> face;
      for (next(token); token == "vertex"; next(token)) {
        double xyz[3];
        for (double& value : xyz) {
          next(token);
          if (!parse_double(token, value)) {
            error("expected a number, got " + quote(token));
          }
          if (const char* problem = coordinate_problem(value)) {
            error(problem);
          }
        }
        face.push_back(merger.add(xyz[0], xyz[1], xyz[2]));
      }
      if (token != "endloop") {
        error("expected 'vertex' or 'endloop', got " + quote(token));
      }
      if (face.size() < 3) {
        error("facet with " + std::to_string(face.size()) + " vertices (need at least 3)");
      }
      expect("endfacet");
      mesh.faces.push_back(std::move(face));
      ++facet_;
      if (!tokens_.next(token)) {
        break;  // a missing "endsolid" loses nothing
      }
    }
    return mesh;
  }

 private:
  void next(std::string_view& token) {
    if (!tokens_.next(token)) {
      fail(path_, "unexpected end of file (facet " + std::to_string(facet_) + ")");
    }
  }
  void expect(std::string_view word) {
    std::string_view token;
    next(token);
    if (token != word) {
      error("expected '" + std::string(word) + "', got " + quote(token));
    }
  }
  // Skips the free-text solid name; leaves `token` on the first keyword after it, or empty.
  void skip_name(std::string_view& token) {
    const std::size_t line = tokens_.line_number();
    while (tokens_.next(token)) {
      if (tokens_.line_number() != line || token == "facet" || token == "endsolid") {
        return;
      }
    }
    token = {};
  }
  [[noreturn]] void error(const std::string& problem) const {
    fail_at(path_, tokens_.line_number(), problem);
  }

  const std::filesystem::path& path_;
  TokenCursor tokens_;
  std::size_t facet_ = 0;
};

}  // namespace

RawMesh read_stl(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  const bool exact_binary_size =
      data.size() >= binary_header_size &&
      data.size() == binary_header_size +
                         std::uint64_t{read_le_u32(data.data() + 80)} * binary_triangle_size;
  if (!exact_binary_size && looks_ascii(data)) {
    return AsciiParser(path, data).parse();
  }
  return read_binary(path, data);
}

}  // namespace envcrust::io::detail
