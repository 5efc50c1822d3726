// Reader of PLY bodies (ascii, binary little and big endian): vertices, normals, colours and
// other vertex properties (kept as attributes), and faces.
//
// We parse PLY (and OFF, OBJ, STL, xyz) ourselves instead of using CGAL's readers because
// those only report "failed", without the file, the line or the problem; users of a
// command-line tool need all three to fix their data.
#include "io_detail.h"
#include "ply_header.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

namespace envcrust::io::detail {

namespace {

// Where the reader is, for messages: element name, record index, record count.
struct Position {
  const char* element = "";
  std::uint64_t index = 0;
  std::uint64_t count = 0;
  [[nodiscard]] std::string where() const {
    return std::string(element) + " " + std::to_string(index);
  }
  [[nodiscard]] std::string of() const { return where() + " of " + std::to_string(count); }
};

class AsciiSource {
 public:
  AsciiSource(const std::filesystem::path& path, std::string_view body, std::size_t first_line,
              const Position& position)
      : path_(path), tokens_(body, first_line), position_(position) {}

  double scalar(PlyType /*type*/) {
    const std::string_view token = next();
    double value = 0.0;
    if (!parse_double(token, value)) {
      error("expected a number, got " + quote(token));
    }
    return value;
  }
  std::int64_t integer(PlyType /*type*/) {
    const std::string_view token = next();
    std::int64_t value = 0;
    if (!parse_int(token, value)) {
      error("expected an integer, got " + quote(token));
    }
    return value;
  }
  void skip(PlyType /*type*/) { next(); }
  // Whether `items` values of `type` may still follow (a cheap bound, exact for binary).
  [[nodiscard]] bool may_hold(std::uint64_t items, PlyType /*type*/) const {
    return items <= tokens_.remaining();
  }
  [[nodiscard]] std::size_t remaining() const { return tokens_.remaining(); }
  [[noreturn]] void error(const std::string& problem) const {
    fail_at(path_, tokens_.line_number(), problem);
  }
  [[noreturn]] void truncated() const {
    fail(path_, "unexpected end of file (" + position_.of() + ")");
  }

 private:
  std::string_view next() {
    std::string_view token;
    if (!tokens_.next(token)) {
      truncated();
    }
    return token;
  }
  const std::filesystem::path& path_;
  TokenCursor tokens_;
  const Position& position_;
};

class BinarySource {
 public:
  BinarySource(const std::filesystem::path& path, std::string_view body, bool big_endian,
               const Position& position)
      : path_(path), body_(body), swap_(big_endian != (std::endian::native == std::endian::big)),
        position_(position) {}

  double scalar(PlyType type) {
    switch (type) {
      case PlyType::Int8: return read<std::int8_t>();
      case PlyType::UInt8: return read<std::uint8_t>();
      case PlyType::Int16: return read<std::int16_t>();
      case PlyType::UInt16: return read<std::uint16_t>();
      case PlyType::Int32: return read<std::int32_t>();
      case PlyType::UInt32: return read<std::uint32_t>();
      case PlyType::Float32: return read<float>();
      case PlyType::Float64: return read<double>();
    }
    return 0.0;
  }
  std::int64_t integer(PlyType type) {
    switch (type) {
      case PlyType::Int8: return read<std::int8_t>();
      case PlyType::UInt8: return read<std::uint8_t>();
      case PlyType::Int16: return read<std::int16_t>();
      case PlyType::UInt16: return read<std::uint16_t>();
      case PlyType::Int32: return read<std::int32_t>();
      case PlyType::UInt32: return read<std::uint32_t>();
      default: break;
    }
    error("expected an integer type");
  }
  void skip(PlyType type) { take(ply_type_size(type)); }
  [[nodiscard]] bool may_hold(std::uint64_t items, PlyType type) const {
    return items <= remaining() / ply_type_size(type);
  }
  [[nodiscard]] std::size_t remaining() const { return body_.size() - pos_; }
  [[noreturn]] void error(const std::string& problem) const {
    fail(path_, position_.where() + ": " + problem);
  }
  [[noreturn]] void truncated() const {
    fail(path_, "truncated binary data (" + position_.of() + ")");
  }

 private:
  const char* take(std::size_t size) {
    if (size > remaining()) {
      truncated();
    }
    const char* bytes = body_.data() + pos_;
    pos_ += size;
    return bytes;
  }
  template <class T>
  T read() {
    char bytes[sizeof(T)];
    std::memcpy(bytes, take(sizeof(T)), sizeof(T));
    if (swap_) {
      std::reverse(bytes, bytes + sizeof(T));
    }
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }
  const std::filesystem::path& path_;
  std::string_view body_;
  std::size_t pos_ = 0;
  bool swap_;
  const Position& position_;
};

std::optional<std::size_t> find_property(const PlyElement& element, std::string_view name) {
  for (std::size_t i = 0; i < element.properties.size(); ++i) {
    if (element.properties[i].name == name) {
      return i;
    }
  }
  return std::nullopt;
}

// Smallest number of bytes (binary) or tokens (ascii) one record of `element` occupies.
std::size_t min_record_size(const PlyElement& element, bool binary) {
  std::size_t size = 0;
  for (const PlyProperty& property : element.properties) {
    size += binary ? ply_type_size(property.is_list ? property.count_type : property.type) : 1;
  }
  return size;
}

// Roles of the properties of the vertex and face elements, checked against the header.
struct Layout {
  std::size_t coordinate[3] = {};
  std::optional<std::size_t> normal[3];
  bool has_normals = false;
  std::optional<std::size_t> face_indices;
  std::optional<std::size_t> radius, label;  ///< balls (`envcrust powercrust --poles`)
  std::optional<std::array<std::size_t, 3>> colour;  ///< red, green, blue
  /// Every other scalar vertex property, kept as an attribute: (property, scalar column).
  std::vector<std::pair<std::size_t, std::size_t>> scalars;
};

// A colour channel as 0..255: integers as they are (16-bit ones scaled down), floats from 0..1.
std::uint8_t colour_channel(double value, PlyType type) {
  double scaled = value;
  if (type == PlyType::UInt16) scaled = value / 257.0;
  if (!ply_type_is_integer(type)) scaled = value * 255.0;
  if (!(scaled > 0)) return 0;  // also NaN
  return static_cast<std::uint8_t>(std::lround(std::min(scaled, 255.0)));
}

// The colour properties (red green blue, as most writers name them; r g b; diffuse_red ...) and
// every other scalar that no role takes, as attributes named like the property.
void find_attributes(const PlyElement& element, Layout& layout, PointAttributes& attributes) {
  static constexpr const char* colour_names[3][3] = {
      {"red", "r", "diffuse_red"}, {"green", "g", "diffuse_green"}, {"blue", "b", "diffuse_blue"}};
  for (const auto& spelling : {0, 1, 2}) {
    std::array<std::size_t, 3> channels{};
    bool all = true;
    for (int c = 0; c < 3; ++c) {
      const auto index = find_property(element, colour_names[c][spelling]);
      all = all && index && !element.properties[*index].is_list;
      if (index) channels[c] = *index;
    }
    if (all) {
      layout.colour = channels;
      break;
    }
  }
  for (std::size_t p = 0; p < element.properties.size(); ++p) {
    const bool is_coordinate = std::find(std::begin(layout.coordinate), std::end(layout.coordinate), p) !=
                               std::end(layout.coordinate);
    const bool is_normal = layout.has_normals && (p == layout.normal[0] || p == layout.normal[1] || p == layout.normal[2]);
    const bool is_colour = layout.colour && std::find(layout.colour->begin(), layout.colour->end(), p) != layout.colour->end();
    if (is_coordinate || is_normal || is_colour || element.properties[p].is_list) continue;
    layout.scalars.emplace_back(p, attributes.names.size());
    attributes.names.push_back(element.properties[p].name);
  }
  attributes.scalars.resize(attributes.names.size());
}

Layout check_vertex_element(const std::filesystem::path& path, const PlyElement& element) {
  Layout layout;
  static constexpr const char* coordinate_names[3] = {"x", "y", "z"};
  static constexpr const char* normal_names[3] = {"nx", "ny", "nz"};
  layout.has_normals = true;
  for (int axis = 0; axis < 3; ++axis) {
    const auto index = find_property(element, coordinate_names[axis]);
    if (!index) {
      fail_at(path, element.line,
              std::string("bad PLY header: vertex element has no property '") +
                  coordinate_names[axis] + "'");
    }
    layout.coordinate[axis] = *index;
    layout.normal[axis] = find_property(element, normal_names[axis]);
    layout.has_normals = layout.has_normals && layout.normal[axis].has_value();
    for (const auto& used : {std::optional<std::size_t>(*index), layout.normal[axis]}) {
      if (used && element.properties[*used].is_list) {
        fail_at(path, element.line,
                "bad PLY header: vertex property '" + element.properties[*used].name +
                    "' must not be a list");
      }
    }
  }
  for (auto [role, name] : {std::pair{&layout.radius, "radius"}, std::pair{&layout.label, "label"}}) {
    *role = find_property(element, name);
    if (*role && element.properties[**role].is_list) *role = std::nullopt;
  }
  if (element.count > max_vertices) {
    fail_at(path, element.line,
            "bad PLY header: " + std::to_string(element.count) + " vertices exceed the limit of " +
                std::to_string(max_vertices));
  }
  return layout;
}

std::size_t check_face_element(const std::filesystem::path& path, const PlyElement& element) {
  auto index = find_property(element, "vertex_indices");
  if (!index) {
    index = find_property(element, "vertex_index");
  }
  if (!index || !element.properties[*index].is_list) {
    fail_at(path, element.line, "bad PLY header: face element has no list property 'vertex_indices'");
  }
  if (!ply_type_is_integer(element.properties[*index].type)) {
    fail_at(path, element.line, "bad PLY header: face vertex indices must have an integer type");
  }
  return *index;
}

template <class Source>
void skip_property(Source& source, const PlyProperty& property) {
  if (!property.is_list) {
    source.skip(property.type);
    return;
  }
  const std::int64_t items = source.integer(property.count_type);
  if (items < 0) {
    source.error("negative list length " + std::to_string(items));
  }
  if (!source.may_hold(static_cast<std::uint64_t>(items), property.type)) {
    source.truncated();
  }
  for (std::int64_t i = 0; i < items; ++i) {
    source.skip(property.type);
  }
}

template <class Source>
void read_face(Source& source, const PlyProperty& property, std::uint64_t vertex_count,
               std::vector<Index>& face) {
  const std::int64_t items = source.integer(property.count_type);
  if (items < 3) {
    source.error("face with " + std::to_string(items) + " vertices (need at least 3)");
  }
  if (!source.may_hold(static_cast<std::uint64_t>(items), property.type)) {
    source.truncated();
  }
  face.reserve(static_cast<std::size_t>(items));
  for (std::int64_t i = 0; i < items; ++i) {
    const std::int64_t vertex = source.integer(property.type);
    if (vertex < 0 || static_cast<std::uint64_t>(vertex) >= vertex_count) {
      source.error("face index " + std::to_string(vertex) + " out of range (" +
                   std::to_string(vertex_count) + " vertices)");
    }
    face.push_back(static_cast<Index>(vertex));
  }
}

template <class Source>
RawMesh read_body(const std::filesystem::path& path, const PlyHeader& header, Source& source,
                  Position& position, bool binary) {
  RawMesh mesh;
  const PlyElement* vertex_element = nullptr;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex") {
      if (vertex_element != nullptr) {
        fail_at(path, element.line, "bad PLY header: second 'vertex' element");
      }
      vertex_element = &element;
    }
  }
  if (vertex_element == nullptr) {
    fail(path, "bad PLY header: no 'vertex' element");
  }
  Layout layout = check_vertex_element(path, *vertex_element);
  find_attributes(*vertex_element, layout, mesh.attributes);
  // Scalar column of each vertex property (none: npos), so a record's values land in one look-up.
  std::vector<std::size_t> scalar_column(vertex_element->properties.size(), std::string::npos);
  for (const auto& [property, column] : layout.scalars) scalar_column[property] = column;
  const std::uint64_t vertex_count = vertex_element->count;

  for (const PlyElement& element : header.elements) {
    const bool is_vertex = &element == vertex_element;
    const bool is_face = element.name == "face";
    const std::size_t face_indices = is_face ? check_face_element(path, element) : 0;
    position = Position{element.name.c_str(), 0, element.count};
    const std::size_t record_size = min_record_size(element, binary);
    if (record_size == 0) {
      continue;  // records without properties occupy no data, whatever their count
    }
    // A header may claim any count: only trust it as far as the remaining data can hold.
    const std::uint64_t fitting = source.remaining() / record_size;
    const bool fixed_size = std::none_of(element.properties.begin(), element.properties.end(),
                                         [](const PlyProperty& p) { return p.is_list; });
    if (binary && fixed_size && element.count > fitting) {
      position.index = fitting;
      source.truncated();
    }
    const auto capacity = static_cast<std::size_t>(std::min(element.count, fitting));
    if (is_vertex) {
      mesh.vertices.reserve(capacity);
      if (layout.has_normals) {
        mesh.normals.reserve(capacity);
      }
      if (layout.radius) mesh.radii.reserve(capacity);
      if (layout.label) mesh.labels.reserve(capacity);
      if (layout.colour) mesh.attributes.colours.reserve(capacity);
      for (auto& column : mesh.attributes.scalars) column.reserve(capacity);
    } else if (is_face) {
      mesh.faces.reserve(capacity);
    }
    for (std::uint64_t record = 0; record < element.count; ++record) {
      position.index = record;
      double coordinate[3] = {};
      double normal[3] = {};
      Colour colour{};
      std::vector<Index> face;
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (is_face && p == face_indices) {
          read_face(source, property, vertex_count, face);
          continue;
        }
        if (!is_vertex || property.is_list) {
          skip_property(source, property);
          continue;
        }
        const double value = source.scalar(property.type);
        if (p == layout.radius) mesh.radii.push_back(value);
        if (p == layout.label) mesh.labels.push_back(value);
        if (scalar_column[p] != std::string::npos)
          mesh.attributes.scalars[scalar_column[p]].push_back(static_cast<float>(value));
        if (layout.colour)
          for (int c = 0; c < 3; ++c)
            if (p == (*layout.colour)[c]) colour[static_cast<std::size_t>(c)] = colour_channel(value, property.type);
        for (int axis = 0; axis < 3; ++axis) {
          if (p == layout.coordinate[axis]) {
            coordinate[axis] = value;
            if (const char* problem = coordinate_problem(value)) {
              source.error(problem);
            }
          }
          if (layout.has_normals && p == *layout.normal[axis]) {
            normal[axis] = value;
            if (!std::isfinite(value)) {
              source.error("non-finite normal");
            }
          }
        }
      }
      if (is_vertex) {
        mesh.vertices.emplace_back(coordinate[0], coordinate[1], coordinate[2]);
        if (layout.has_normals) {
          mesh.normals.emplace_back(normal[0], normal[1], normal[2]);
        }
        if (layout.colour) mesh.attributes.colours.push_back(colour);
      } else if (is_face) {
        mesh.faces.push_back(std::move(face));
      }
    }
  }
  return mesh;
}

}  // namespace

RawMesh read_ply(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  const PlyHeader header = parse_ply_header(path, data);
  const std::string_view body = std::string_view(data).substr(header.body_offset);
  Position position;
  if (header.format == PlyFormat::Ascii) {
    AsciiSource source(path, body, header.body_line, position);
    return read_body(path, header, source, position, false);
  }
  BinarySource source(path, body, header.format == PlyFormat::BinaryBigEndian, position);
  return read_body(path, header, source, position, true);
}

}  // namespace envcrust::io::detail
