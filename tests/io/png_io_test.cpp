// Tests of PNG writing and reading: exact round trip, reproducible bytes, atomic failure.
#include "envcrust/io.h"
#include "io_test_support.h"

namespace envcrust::io {
namespace {

using testing::io_error_of;

class PngIo : public testing::TempDirTest {};

render::Image gradient(int width, int height) {
  render::Image image{width, height, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.rgb.insert(image.rgb.end(), {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 13),
                                         static_cast<std::uint8_t>((x * y) % 256)});
  return image;
}

TEST_F(PngIo, round_trips_exactly) {
  const auto image = gradient(37, 21);
  write_png(path("a.png"), image);
  const auto back = read_png(path("a.png"));
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 21);
  EXPECT_EQ(back.rgb, image.rgb);
}

TEST_F(PngIo, same_image_gives_the_same_bytes) {
  write_png(path("a.png"), gradient(16, 16));
  write_png(path("b.png"), gradient(16, 16));
  EXPECT_EQ(read_binary_file(path("a.png")), read_binary_file(path("b.png")));
  const auto bytes = read_binary_file(path("a.png"));
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(std::string(bytes.begin() + 1, bytes.begin() + 4), "PNG");
}

TEST_F(PngIo, image_with_wrong_byte_count_is_refused_and_nothing_is_written) {
  const render::Image broken{4, 4, std::vector<std::uint8_t>(10)};
  const auto file = path("x.png");
  EXPECT_EQ(io_error_of([&] { write_png(file, broken); }),
            file.string() + ": cannot write an image of 4 x 4 pixels from 10 bytes");
  EXPECT_TRUE(files().empty());
}

TEST_F(PngIo, non_png_file_is_refused_with_its_name) {
  const auto file = write("fake.png", "this is not a png file at all");
  EXPECT_EQ(io_error_of([&] { read_png(file); }).rfind(file.string() + ": not a PNG file (", 0), 0u);
  const auto missing = path("missing.png");
  EXPECT_EQ(io_error_of([&] { read_png(missing); }), missing.string() + ": cannot open file");
}

TEST_F(PngIo, binary_file_is_read_byte_for_byte) {
  const std::string bytes("a\0b\xff\n", 5);
  const auto file = write("f.bin", bytes);
  EXPECT_EQ(read_binary_file(file), std::vector<std::uint8_t>({'a', 0, 'b', 0xff, '\n'}));
  EXPECT_EQ(io_error_of([&] { read_binary_file(path("none.ttf")); }), path("none.ttf").string() + ": cannot open file");
}

}  // namespace
}  // namespace envcrust::io
