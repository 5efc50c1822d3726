// Drawing captions into an Image with FreeType, from font bytes in memory.
#pragma once

#include "envcrust/render.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <string>

namespace envcrust::render::detail {

/// One font face at one pixel size. Not thread-safe (FreeType faces are not).
class TextRenderer {
 public:
  /// @throws InvalidInput "render: cannot use the font (FreeType error N)".
  explicit TextRenderer(const Font& font);
  ~TextRenderer();
  TextRenderer(const TextRenderer&) = delete;
  TextRenderer& operator=(const TextRenderer&) = delete;

  [[nodiscard]] int ascender() const { return ascender_; }
  [[nodiscard]] int descender() const { return descender_; }  ///< below the baseline, >= 0
  /// Advance width of a UTF-8 text in pixels.
  int width(const std::string& text);
  /// The text, shortened with "..." at the end until it fits `max_width` pixels.
  std::string fit(const std::string& text, int max_width);
  /// Blend the text into `image` with its pen starting at (x, baseline); clipped to the image.
  void draw(Image& image, int x, int baseline, const std::string& text, Color color);

 private:
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  int ascender_ = 0, descender_ = 0;
};

}  // namespace envcrust::render::detail
