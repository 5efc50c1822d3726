// compose_grid puts panels, captions and the title where GridOptions documents them.
#include "fonts.h"
#include "scenes.h"

#include "envcrust/errors.h"

#include <gtest/gtest.h>

namespace envcrust::render {
namespace {

Image solid(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image{width, height, {}};
  for (int i = 0; i < width * height; ++i) image.rgb.insert(image.rgb.end(), {r, g, b});
  return image;
}

bool has_colour(const Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const auto* p = testing::pixel(image, x, y);
  return p[0] == r && p[1] == g && p[2] == b;
}

/// Pixels darker than mid-grey in the rectangle [x0, x1) x [y0, y1) (text on white).
int dark_pixels(const Image& image, int x0, int y0, int x1, int y1) {
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) count += testing::pixel(image, x, y)[0] < 128 ? 1 : 0;
  return count;
}

std::vector<Panel> three_panels() {
  return {{solid(40, 30, 255, 0, 0), ""}, {solid(20, 20, 0, 255, 0), ""}, {solid(40, 30, 0, 0, 255), ""}};
}

// Cells 40 x 30, gap 5, 2 x 2: 95 x 75. Panel 1 (20 x 20) is centred in cell (0, 1) which
// starts at (50, 5): it covers [60, 80) x [10, 30). Panel 2 fills cell (1, 0) at (5, 40).
TEST(Grid, panels_go_to_their_documented_cells) {
  GridOptions options;
  options.rows = 2;
  options.columns = 2;
  options.gap_px = 5;
  const Image grid = compose_grid(three_panels(), options, std::nullopt);
  ASSERT_EQ(grid.width, 95);
  ASSERT_EQ(grid.height, 75);
  EXPECT_TRUE(has_colour(grid, 5, 5, 255, 0, 0));
  EXPECT_TRUE(has_colour(grid, 44, 34, 255, 0, 0));
  EXPECT_TRUE(has_colour(grid, 45, 34, 255, 255, 255));  // the gap
  EXPECT_TRUE(has_colour(grid, 60, 10, 0, 255, 0));
  EXPECT_TRUE(has_colour(grid, 79, 29, 0, 255, 0));
  EXPECT_TRUE(has_colour(grid, 59, 10, 255, 255, 255));  // beside the smaller panel
  EXPECT_TRUE(has_colour(grid, 5, 40, 0, 0, 255));
  EXPECT_TRUE(has_colour(grid, 44, 69, 0, 0, 255));
  EXPECT_TRUE(has_colour(grid, 70, 55, 255, 255, 255));  // the empty fourth cell
}

TEST(Grid, default_layout_is_one_row) {
  const Image grid = compose_grid(three_panels(), GridOptions{}, std::nullopt);
  EXPECT_EQ(grid.width, 8 + 3 * (40 + 8));
  EXPECT_EQ(grid.height, 8 + 30 + 8);
  EXPECT_TRUE(has_colour(grid, 8 + 2 * 48, 8, 0, 0, 255));
}

// Captions take a band of 1.5 * 18 = 27 pixels under each row, the title one above the grid.
TEST(Grid, captions_and_title_appear_where_asked) {
  const auto font = testing::test_font();
  if (!font) GTEST_SKIP() << "font " << testing::kFontPath << " not installed";
  auto panels = three_panels();
  panels[0].caption = "cylinder";
  panels[2].caption = "trefoil";
  GridOptions options;
  options.title = "Title";
  const Image grid = compose_grid(panels, options, font);
  ASSERT_EQ(grid.width, 8 + 3 * 48);
  ASSERT_EQ(grid.height, 8 + 27 + 30 + 27 + 8);
  const int band_top = 8 + 27 + 30;
  EXPECT_GT(dark_pixels(grid, 8, band_top, 48, band_top + 27), 20);        // under panel 0
  EXPECT_EQ(dark_pixels(grid, 56, band_top, 96, band_top + 27), 0);        // panel 1: none
  EXPECT_GT(dark_pixels(grid, 104, band_top, 144, band_top + 27), 20);     // under panel 2
  EXPECT_GT(dark_pixels(grid, 8, 8, grid.width - 8, 8 + 27), 20);          // the title
  EXPECT_TRUE(has_colour(grid, 8, 8 + 27, 255, 0, 0));                     // panel 0 below it
}

TEST(Grid, without_a_font_the_layout_is_the_same_and_text_is_left_out) {
  auto panels = three_panels();
  panels[0].caption = "cylinder";
  GridOptions options;
  options.title = "Title";
  const Image grid = compose_grid(panels, options, std::nullopt);
  EXPECT_EQ(grid.height, 8 + 27 + 30 + 27 + 8);
  EXPECT_EQ(dark_pixels(grid, 0, 0, grid.width, 8 + 27), 0);
  EXPECT_EQ(dark_pixels(grid, 0, 8 + 27 + 30, grid.width, grid.height), 0);
}

template <class E>
void expect_grid_error(const std::vector<Panel>& panels, const GridOptions& options, const std::string& message) {
  EXPECT_EQ(testing::message_of<E>([&] { compose_grid(panels, options, std::nullopt); }), message);
}

TEST(Grid, impossible_layouts_are_refused) {
  GridOptions small;
  small.rows = 1;
  small.columns = 2;
  expect_grid_error<InvalidOptions>(three_panels(), small, "GridOptions: a 1 x 2 grid has no room for 3 panels");
  GridOptions half;
  half.columns = 2;
  expect_grid_error<InvalidOptions>(three_panels(), half,
                                    "GridOptions.rows and columns must both be 0 (one row) or both > 0 (got 0 x 2)");
  expect_grid_error<InvalidInput>({}, GridOptions{}, "compose_grid: no panel to lay out");
  std::vector<Panel> broken = {{Image{4, 4, {}}, ""}};
  expect_grid_error<InvalidInput>(broken, GridOptions{}, "compose_grid: panel 0 has 0 bytes for 4 x 4 pixels");
}

}  // namespace
}  // namespace envcrust::render
