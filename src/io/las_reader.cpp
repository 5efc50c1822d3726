// Reader of LAS point clouds (ASPRS LAS 1.0 to 1.4, point data formats 0 to 10): positions
// with the header's scale and offset applied, RGB as colours, intensity and classification
// as scalars. Compressed files (LAZ) are refused with a way to decompress them: reading them
// would need LASzip, which Debian does not package as a library.
#include "io_detail.h"

#include "envcrust/io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace envcrust::io::detail {
namespace {

// Bytes of the fields each point data format defines; a record may be longer (extra bytes,
// skipped). Formats 4, 5, 9 and 10 carry a wave packet, 8 and 10 near-infrared.
constexpr std::array<std::size_t, 11> kCoreRecordLength = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
// Where RGB starts in a record; 0: the format has none.
constexpr std::array<std::size_t, 11> kRgbOffset = {0, 0, 20, 28, 0, 28, 0, 30, 30, 0, 30};

// Header bytes each version defines (1.3 adds the waveform start, 1.4 extended counts).
std::size_t header_bytes(unsigned minor) { return minor >= 4 ? 375 : minor == 3 ? 235 : 227; }

template <class T>
T little_endian(const std::string& data, std::size_t at) {
  T value;
  std::memcpy(&value, data.data() + at, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    auto* bytes = reinterpret_cast<unsigned char*>(&value);
    std::reverse(bytes, bytes + sizeof(T));
  }
  return value;
}

std::string number_text(double value) {
  std::string text;
  append_double(text, value);
  return text;
}

struct LasHeader {
  unsigned minor = 0;
  unsigned format = 0;
  std::size_t record_length = 0;
  std::uint64_t point_offset = 0;
  std::uint64_t count = 0;
  std::array<double, 3> scale{}, offset{};
};

[[noreturn]] void refuse_compressed(const std::filesystem::path& path) {
  const std::filesystem::path out =
      path.parent_path() / (path.stem().string() + (extension_of(path) == "laz" ? ".las" : "-decompressed.las"));
  fail(path, "compressed LAS (LAZ) is not read; decompress it first, e.g. with `laszip -i " + path.string() +
                 " -o " + out.string() + "` or `pdal translate " + path.string() + " " + out.string() + "`");
}

LasHeader read_header(const std::filesystem::path& path, const std::string& data) {
  if (data.size() < 4 || data.compare(0, 4, "LASF") != 0) fail(path, "not a LAS file (it does not start with 'LASF')");
  if (data.size() < 227)
    fail(path, "truncated header (" + std::to_string(data.size()) + " bytes; a LAS header has at least 227)");
  LasHeader h;
  const unsigned major = static_cast<unsigned char>(data[24]);
  h.minor = static_cast<unsigned char>(data[25]);
  if (major != 1 || h.minor > 4)
    fail(path, "LAS version " + std::to_string(major) + "." + std::to_string(h.minor) + " is not read (1.0 to 1.4 are)");
  const std::size_t needed = header_bytes(h.minor);
  const std::string version = "LAS 1." + std::to_string(h.minor);
  if (data.size() < needed)
    fail(path, "truncated header (" + std::to_string(data.size()) + " bytes; a " + version + " header has " +
                   std::to_string(needed) + ")");
  const std::size_t header_size = little_endian<std::uint16_t>(data, 94);
  if (header_size < needed)
    fail(path, "header size " + std::to_string(header_size) + " is below the " + std::to_string(needed) +
                   " bytes of a " + version + " header");
  h.point_offset = little_endian<std::uint32_t>(data, 96);
  const unsigned format_id = static_cast<unsigned char>(data[104]);
  // LASzip marks its files by setting bit 7 (and sometimes 6) of the format id.
  if ((format_id & 0xC0) != 0) refuse_compressed(path);
  h.format = format_id;
  if (h.format > 10) fail(path, "point data format " + std::to_string(h.format) + " is not defined (0 to 10 are)");
  h.record_length = little_endian<std::uint16_t>(data, 105);
  if (h.record_length < kCoreRecordLength[h.format])
    fail(path, "point record length " + std::to_string(h.record_length) + " is too small for point data format " +
                   std::to_string(h.format) + " (" + std::to_string(kCoreRecordLength[h.format]) + " bytes)");
  h.count = little_endian<std::uint32_t>(data, 107);
  // LAS 1.4 counts in 64 bits, and its legacy count is 0 for formats 6 to 10 (or for over 2^32 points).
  if (h.minor >= 4) {
    if (const auto extended = little_endian<std::uint64_t>(data, 247); extended != 0) h.count = extended;
  }
  const char* axes = "xyz";
  for (std::size_t k = 0; k < 3; ++k) {
    h.scale[k] = little_endian<double>(data, 131 + 8 * k);
    h.offset[k] = little_endian<double>(data, 155 + 8 * k);
    if (!std::isfinite(h.scale[k]) || h.scale[k] == 0)
      fail(path, std::string(1, axes[k]) + " scale factor " + number_text(h.scale[k]) + " is not a usable scale");
    if (coordinate_problem(h.offset[k]))
      fail(path, std::string(1, axes[k]) + " offset " + number_text(h.offset[k]) + " is not a usable offset");
  }
  if (h.point_offset < header_size)
    fail(path, "point data offset " + std::to_string(h.point_offset) + " lies inside the " +
                   std::to_string(header_size) + "-byte header");
  if (h.point_offset > data.size())
    fail(path, "point data offset " + std::to_string(h.point_offset) + " is beyond the end of the file (" +
                   std::to_string(data.size()) + " bytes)");
  if (h.count == 0) fail(path, "no points");
  const std::uint64_t available = (data.size() - h.point_offset) / h.record_length;
  if (h.count > available)
    fail(path, "truncated point data: the header announces " + std::to_string(h.count) + " points of " +
                   std::to_string(h.record_length) + " bytes, the file holds " + std::to_string(available));
  return h;
}

// LAS colours are 16-bit; many writers store 8-bit values in them unscaled. Values all within
// 0..255 are taken as 8-bit, else they are scaled down (as the PLY reader does 16-bit ones).
void read_colours(const std::string& data, const LasHeader& h, std::vector<Colour>& colours) {
  const std::size_t at = kRgbOffset[h.format];
  std::vector<std::array<std::uint16_t, 3>> raw(h.count);
  std::uint16_t largest = 0;
  for (std::uint64_t i = 0; i < h.count; ++i) {
    const std::size_t base = h.point_offset + i * h.record_length + at;
    for (std::size_t k = 0; k < 3; ++k) {
      raw[i][k] = little_endian<std::uint16_t>(data, base + 2 * k);
      largest = std::max(largest, raw[i][k]);
    }
  }
  const bool is_16_bit = largest > 255;
  colours.resize(h.count);
  for (std::uint64_t i = 0; i < h.count; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      colours[i][k] = static_cast<std::uint8_t>(is_16_bit ? std::lround(raw[i][k] / 257.0) : raw[i][k]);
}

}  // namespace

AttributedPoints read_las(const std::filesystem::path& path) {
  if (extension_of(path) == "laz") refuse_compressed(path);
  const std::string data = read_file(path);
  const LasHeader h = read_header(path, data);
  AttributedPoints result;
  auto& points = result.points.points;
  points.reserve(h.count);
  std::vector<float> intensity(h.count), classification(h.count);
  // Formats 0-5 keep the class in the low 5 bits (the others are flags); 6-10 use a byte.
  const bool is_legacy = h.format < 6;
  for (std::uint64_t i = 0; i < h.count; ++i) {
    const std::size_t base = h.point_offset + i * h.record_length;
    double xyz[3];
    for (std::size_t k = 0; k < 3; ++k) {
      xyz[k] = static_cast<double>(little_endian<std::int32_t>(data, base + 4 * k)) * h.scale[k] + h.offset[k];
      if (const char* problem = coordinate_problem(xyz[k])) fail(path, "point " + std::to_string(i + 1) + ": " + problem);
    }
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
    intensity[i] = little_endian<std::uint16_t>(data, base + 12);
    const auto class_byte = static_cast<unsigned char>(data[base + (is_legacy ? 15 : 16)]);
    classification[i] = static_cast<float>(is_legacy ? class_byte & 0x1F : class_byte);
  }
  if (kRgbOffset[h.format] != 0) read_colours(data, h, result.attributes.colours);
  result.attributes.names = {"intensity", "classification"};
  result.attributes.scalars = {std::move(intensity), std::move(classification)};
  return result;
}

}  // namespace envcrust::io::detail
