#include "base64.h"

#include "html/page_reader.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace envcrust::cli::html {
namespace {

std::string encoded(const std::string& bytes) {
  std::ostringstream out;
  write_base64(out, bytes.data(), bytes.size());
  return out.str();
}

TEST(Base64, rfc_4648_test_vectors_are_reproduced) {
  EXPECT_EQ(encoded(""), "");
  EXPECT_EQ(encoded("f"), "Zg==");
  EXPECT_EQ(encoded("fo"), "Zm8=");
  EXPECT_EQ(encoded("foo"), "Zm9v");
  EXPECT_EQ(encoded("foob"), "Zm9vYg==");
  EXPECT_EQ(encoded("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encoded("foobar"), "Zm9vYmFy");
}

TEST(Base64, every_byte_value_round_trips_across_block_boundaries) {
  // The encoder writes in blocks of 4096 triples: sizes around one block and beyond.
  for (const std::size_t size : {std::size_t{12287}, std::size_t{12288}, std::size_t{12289}, std::size_t{40000}}) {
    std::string bytes(size, '\0');
    for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>((i * 7 + i / 256) & 0xff);
    const std::string text = encoded(bytes);
    EXPECT_EQ(text.size(), base64_length(size));
    const auto decoded = envcrust::testing::decode_base64(text);
    ASSERT_EQ(decoded.size(), size);
    EXPECT_EQ(std::string(decoded.begin(), decoded.end()), bytes) << "size " << size;
  }
}

}  // namespace
}  // namespace envcrust::cli::html
