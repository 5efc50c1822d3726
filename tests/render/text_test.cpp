// Caption text: drawn with the given font, shortened to fit, refused when the font is bad.
#include "fonts.h"
#include "scenes.h"
#include "text.h"

#include "envcrust/errors.h"

#include <gtest/gtest.h>

namespace envcrust::render {
namespace {

Image white(int width, int height) {
  return Image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3, 255)};
}

TEST(Text, unparsable_font_bytes_are_refused) {
  const Font garbage{std::vector<std::uint8_t>(256, 'x')};
  EXPECT_EQ(testing::message_of<InvalidInput>([&] { compose_grid({{white(16, 16), "caption"}}, GridOptions{}, garbage); }),
            "render: cannot use the font (FreeType error 2)");  // unknown file format
}

TEST(Text, check_font_refuses_what_freetype_cannot_use_before_drawing) {
  const Font garbage{std::vector<std::uint8_t>(256, 'x')};
  EXPECT_EQ(testing::message_of<InvalidInput>([&] { check_font(garbage); }),
            "render: cannot use the font (FreeType error 2)");
  const auto font = testing::test_font();
  if (!font) GTEST_SKIP() << "font " << testing::kFontPath << " not installed";
  EXPECT_NO_THROW(check_font(*font));
  EXPECT_THROW(check_font(Font{font->data, 2}), InvalidOptions);  // 2 pixels high
}

TEST(Text, a_long_caption_is_shortened_to_its_cell) {
  const auto font = testing::test_font();
  if (!font) GTEST_SKIP() << "font " << testing::kFontPath << " not installed";
  const Image grid = compose_grid({{white(60, 20), std::string(200, 'W')}}, GridOptions{}, font);
  // Nothing is drawn into the side gaps: the caption stays within the 60-pixel cell.
  for (int y = 0; y < grid.height; ++y) {
    for (const int x : {0, 7, grid.width - 8, grid.width - 1})
      EXPECT_EQ(testing::pixel(grid, x, y)[0], 255) << x << "," << y;
  }
}

// fit keeps the longest prefix that fits with "..." after it; a 5,000-character title is
// shortened in one pass over its glyphs (it took 24 s when every prefix was re-measured).
TEST(Text, fit_keeps_the_longest_prefix_that_fits) {
  const auto font = testing::test_font();
  if (!font) GTEST_SKIP() << "font " << testing::kFontPath << " not installed";
  detail::TextRenderer text(*font);
  const std::string long_text = std::string(5000, 'W') + "ö";
  for (const int width : {0, 10, 60, 333}) {
    const std::string shown = text.fit(long_text, width);
    SCOPED_TRACE(width);
    if (shown.empty()) {
      EXPECT_GT(text.width("..."), width);
      continue;
    }
    ASSERT_GE(shown.size(), 3u);
    EXPECT_EQ(shown.substr(shown.size() - 3), "...");
    EXPECT_LE(text.width(shown), width);
    const std::string prefix = shown.substr(0, shown.size() - 3);
    EXPECT_EQ(long_text.rfind(prefix, 0), 0u);
    EXPECT_GT(text.width(prefix + "W..."), width);
  }
  EXPECT_EQ(text.fit("short", 1000), "short");
}

TEST(Text, same_caption_gives_the_same_bytes) {
  const auto font = testing::test_font();
  if (!font) GTEST_SKIP() << "font " << testing::kFontPath << " not installed";
  const std::vector<Panel> panels = {{white(80, 20), "Möbius band"}};
  EXPECT_EQ(compose_grid(panels, GridOptions{}, font).rgb, compose_grid(panels, GridOptions{}, font).rgb);
}

}  // namespace
}  // namespace envcrust::render
