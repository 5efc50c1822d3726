// Private PLY header model shared by the PLY header parser and the PLY body reader.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace envcrust::io::detail {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  ///< item type for lists
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;  ///< only for lists
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::size_t line = 0;  ///< header line of the `element` keyword
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  ///< first byte after the end_header line
  std::size_t body_line = 0;    ///< line number of the first body line (ascii)
};

/// Size in bytes of a binary PLY scalar.
std::size_t ply_type_size(PlyType type);

/// True for the integer PLY types.
bool ply_type_is_integer(PlyType type);

/// Parse the header of a PLY file. @throws IoError "FILE:LINE: bad PLY header: ...".
PlyHeader parse_ply_header(const std::filesystem::path& path, std::string_view data);

}  // namespace envcrust::io::detail
