// Parser of PLY headers: format line, elements and their scalar and list properties.
#include "ply_header.h"

#include "io_detail.h"

#include <charconv>
#include <optional>

namespace envcrust::io::detail {

namespace {

std::optional<PlyType> type_from_name(std::string_view name) {
  struct Entry {
    std::string_view name;
    PlyType type;
  };
  static constexpr Entry entries[] = {
      {"char", PlyType::Int8},       {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},     {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},   {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},     {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},   {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64},
  };
  for (const Entry& entry : entries) {
    if (entry.name == name) {
      return entry.type;
    }
  }
  return std::nullopt;
}

[[noreturn]] void bad_header(const std::filesystem::path& path, std::size_t line,
                             const std::string& problem) {
  fail_at(path, line, "bad PLY header: " + problem);
}

PlyType parse_type(const std::filesystem::path& path, std::size_t line, std::string_view name) {
  const auto type = type_from_name(name);
  if (!type) {
    bad_header(path, line, "unknown property type " + quote(name));
  }
  return *type;
}

}  // namespace

std::size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 8;
}

bool ply_type_is_integer(PlyType type) {
  return type != PlyType::Float32 && type != PlyType::Float64;
}

PlyHeader parse_ply_header(const std::filesystem::path& path, std::string_view data) {
  PlyHeader header;
  LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  if (!lines.next(line) || line != "ply") {
    bad_header(path, 1, "expected 'ply' on the first line");
  }
  bool have_format = false;
  while (lines.next(line)) {
    const std::size_t number = lines.line_number();
    split_tokens(line, tokens);
    if (tokens.empty()) {
      continue;
    }
    const std::string_view keyword = tokens[0];
    if (keyword == "comment" || keyword == "obj_info") {
      continue;
    }
    if (keyword == "end_header") {
      if (!have_format) {
        bad_header(path, number, "missing 'format' line");
      }
      header.body_offset = data.size() - lines.remaining();
      header.body_line = number + 1;
      return header;
    }
    if (keyword == "format") {
      if (have_format || tokens.size() != 3) {
        bad_header(path, number, "expected one 'format ENCODING 1.0' line");
      }
      if (tokens[1] == "ascii") {
        header.format = PlyFormat::Ascii;
      } else if (tokens[1] == "binary_little_endian") {
        header.format = PlyFormat::BinaryLittleEndian;
      } else if (tokens[1] == "binary_big_endian") {
        header.format = PlyFormat::BinaryBigEndian;
      } else {
        bad_header(path, number, "unknown format " + quote(tokens[1]));
      }
      have_format = true;
    } else if (keyword == "element") {
      std::uint64_t count = 0;
      const std::string_view count_text = tokens.size() == 3 ? tokens[2] : std::string_view();
      const auto [end, ec] =
          std::from_chars(count_text.data(), count_text.data() + count_text.size(), count);
      if (tokens.size() != 3 || ec != std::errc() || end != count_text.data() + count_text.size()) {
        bad_header(path, number, "expected 'element NAME COUNT'");
      }
      header.elements.push_back(PlyElement{std::string(tokens[1]), count, {}, number});
    } else if (keyword == "property") {
      if (header.elements.empty()) {
        bad_header(path, number, "property before any element");
      }
      PlyProperty property;
      if (tokens.size() == 5 && tokens[1] == "list") {
        property.is_list = true;
        property.count_type = parse_type(path, number, tokens[2]);
        property.type = parse_type(path, number, tokens[3]);
        property.name = tokens[4];
        if (!ply_type_is_integer(property.count_type)) {
          bad_header(path, number, "list length type must be an integer type");
        }
      } else if (tokens.size() == 3 && tokens[1] != "list") {
        property.type = parse_type(path, number, tokens[1]);
        property.name = tokens[2];
      } else {
        bad_header(path, number,
                   "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      bad_header(path, number, "unknown keyword " + quote(keyword));
    }
  }
  fail(path, "bad PLY header: missing 'end_header'");
}

}  // namespace envcrust::io::detail
