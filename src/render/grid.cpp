// compose_grid: panels side by side in a grid, captions under them, a title above.
#include "text.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace envcrust::render {
namespace {

void check_grid(const std::vector<Panel>& panels, const GridOptions& options) {
  if (panels.empty()) throw InvalidInput("compose_grid: no panel to lay out");
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Image& image = panels[i].image;
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
      throw InvalidInput("compose_grid: panel " + std::to_string(i) + " has " +
                         std::to_string(image.rgb.size()) + " bytes for " + std::to_string(image.width) +
                         " x " + std::to_string(image.height) + " pixels");
    }
  }
  if ((options.rows == 0) != (options.columns == 0) || options.rows < 0 || options.columns < 0) {
    throw InvalidOptions("GridOptions.rows and columns must both be 0 (one row) or both > 0 (got " +
                         std::to_string(options.rows) + " x " + std::to_string(options.columns) + ")");
  }
  if (options.rows > 0 && static_cast<std::size_t>(options.rows) * options.columns < panels.size()) {
    throw InvalidOptions("GridOptions: a " + std::to_string(options.rows) + " x " +
                         std::to_string(options.columns) + " grid has no room for " +
                         std::to_string(panels.size()) + " panels");
  }
  if (options.gap_px < 0 || options.gap_px > 1000) {
    throw InvalidOptions("GridOptions.gap_px must be in [0, 1000] (got " + std::to_string(options.gap_px) + ")");
  }
}

std::uint8_t byte_of(float channel) {
  return static_cast<std::uint8_t>(std::lround(255 * std::clamp(channel, 0.0f, 1.0f)));
}

void blit(Image& target, const Image& source, int x0, int y0) {
  for (int y = 0; y < source.height; ++y) {
    std::copy_n(&source.rgb[static_cast<std::size_t>(y) * source.width * 3], source.width * 3,
                &target.rgb[(static_cast<std::size_t>(y0 + y) * target.width + x0) * 3]);
  }
}

/// Draw `text` centred in the band [x, x + width) x [y, y + height), shortened to fit.
}  // namespace

void check_font(const Font& font) { (void)detail::TextRenderer(font); }

namespace {

void draw_centred(detail::TextRenderer& text, Image& image, const std::string& line, int x, int y,
                  int width, int height, Color color) {
  const std::string shown = text.fit(line, width);
  const int baseline = y + (height - (text.ascender() + text.descender())) / 2 + text.ascender();
  text.draw(image, x + (width - text.width(shown)) / 2, baseline, shown, color);
}

}  // namespace

Image compose_grid(const std::vector<Panel>& panels, const GridOptions& options,
                   const std::optional<Font>& font) {
  check_grid(panels, options);
  std::unique_ptr<detail::TextRenderer> text;
  if (font) text = std::make_unique<detail::TextRenderer>(*font);

  const int count = static_cast<int>(panels.size());
  const int columns = options.columns > 0 ? options.columns : count;
  const int rows = options.rows > 0 ? options.rows : 1;
  int cell_w = 0, cell_h = 0;
  for (const auto& panel : panels) {
    cell_w = std::max(cell_w, panel.image.width);
    cell_h = std::max(cell_h, panel.image.height);
  }
  const int band = static_cast<int>(std::lround(1.5 * (font ? font->pixel_height : Font{}.pixel_height)));
  const bool has_captions = std::any_of(panels.begin(), panels.end(), [](const Panel& p) { return !p.caption.empty(); });
  const int caption_h = has_captions ? band : 0;
  const int title_h = options.title.empty() ? 0 : band;
  const int g = options.gap_px;

  Image image;
  image.width = g + columns * (cell_w + g);
  image.height = g + title_h + rows * (cell_h + caption_h + g);
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  const std::uint8_t bg[3] = {byte_of(options.background.r), byte_of(options.background.g),
                              byte_of(options.background.b)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = bg[i % 3];

  for (int i = 0; i < count; ++i) {
    const int x = g + (i % columns) * (cell_w + g);
    const int y = g + title_h + (i / columns) * (cell_h + caption_h + g);
    const Image& panel = panels[i].image;
    blit(image, panel, x + (cell_w - panel.width) / 2, y + (cell_h - panel.height) / 2);
    if (text && !panels[i].caption.empty())
      draw_centred(*text, image, panels[i].caption, x, y + cell_h, cell_w, caption_h, options.text);
  }
  if (text && title_h > 0) draw_centred(*text, image, options.title, g, g, image.width - 2 * g, title_h, options.text);
  return image;
}

}  // namespace envcrust::render
