#include "base64.h"

#include <array>
#include <cstdint>
#include <ostream>

namespace envcrust::cli::html {

void write_base64(std::ostream& out, const void* data, std::size_t size) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  // Encoded in blocks, so a large array is neither copied whole nor written a character at a time.
  std::array<char, 4 * 4096> block{};
  std::size_t used = 0;
  for (std::size_t i = 0; i < size; i += 3) {
    const std::size_t left = size - i;
    const std::uint32_t triple = (std::uint32_t{bytes[i]} << 16) | (left > 1 ? std::uint32_t{bytes[i + 1]} << 8 : 0) |
                                 (left > 2 ? std::uint32_t{bytes[i + 2]} : 0);
    block[used++] = kAlphabet[(triple >> 18) & 63];
    block[used++] = kAlphabet[(triple >> 12) & 63];
    block[used++] = left > 1 ? kAlphabet[(triple >> 6) & 63] : '=';
    block[used++] = left > 2 ? kAlphabet[triple & 63] : '=';
    if (used == block.size()) {
      out.write(block.data(), static_cast<std::streamsize>(used));
      used = 0;
    }
  }
  out.write(block.data(), static_cast<std::streamsize>(used));
}

}  // namespace envcrust::cli::html
