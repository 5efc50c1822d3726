// Reading an HTML report back in tests: a data block's text, base64 decoded into typed values.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace envcrust::testing {

/// The text of the element `<script ... id="ID">` (empty when absent).
inline std::string script_text(const std::string& page, const std::string& id) {
  const std::string open = "id=\"" + id + "\">";
  const auto start = page.find(open);
  if (start == std::string::npos) return {};
  const auto begin = start + open.size();
  return page.substr(begin, page.find("</script>", begin) - begin);
}

/// RFC 4648 base64 decoded (padding required, no line breaks); a bad character fails the test.
inline std::vector<std::uint8_t> decode_base64(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<std::uint8_t> out;
  EXPECT_EQ(text.size() % 4, 0u) << "base64 text of " << text.size() << " characters";
  for (std::size_t i = 0; i + 3 < text.size(); i += 4) {
    std::uint32_t triple = 0;
    int bytes = 3;
    for (int k = 0; k < 4; ++k) {
      const char c = text[i + k];
      if (c == '=') {
        bytes = std::min(bytes, k - 1);
        triple <<= 6;
        continue;
      }
      const int v = value(c);
      EXPECT_GE(v, 0) << "character '" << c << "' at " << i + k;
      triple = (triple << 6) | static_cast<std::uint32_t>(std::max(v, 0));
    }
    for (int k = 0; k < bytes; ++k) out.push_back(static_cast<std::uint8_t>(triple >> (16 - 8 * k)));
  }
  return out;
}

/// A data block decoded as values of type T.
template <class T>
std::vector<T> decode_block(const std::string& page, const std::string& id) {
  const auto bytes = decode_base64(script_text(page, id));
  EXPECT_EQ(bytes.size() % sizeof(T), 0u) << id;
  std::vector<T> values(bytes.size() / sizeof(T));
  if (!values.empty()) std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

}  // namespace envcrust::testing
