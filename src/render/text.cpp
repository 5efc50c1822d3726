// FreeType text: glyphs rendered as 8-bit coverage and blended over the image.
#include "text.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace envcrust::render::detail {
namespace {

void check(FT_Error error) {
  if (error != 0) {
    throw InvalidInput("render: cannot use the font (FreeType error " + std::to_string(error) + ")");
  }
}

/// Code points of a UTF-8 string; a malformed byte becomes '?'.
std::vector<char32_t> decode_utf8(const std::string& text) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const int extra = lead < 0x80 ? 0 : (lead >> 5) == 6 ? 1 : (lead >> 4) == 14 ? 2 : (lead >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + extra >= text.size()) {
      out.push_back(U'?');
      ++i;
      continue;
    }
    char32_t cp = extra == 0 ? lead : lead & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      ok = ok && (next >> 6) == 2;
      cp = (cp << 6) | (next & 0x3F);
    }
    out.push_back(ok ? cp : U'?');
    i += ok ? extra + 1 : 1;
  }
  return out;
}

}  // namespace

TextRenderer::TextRenderer(const Font& font) {
  if (font.pixel_height < 4 || font.pixel_height > 512) {
    throw InvalidOptions("Font.pixel_height must be in [4, 512] (got " + std::to_string(font.pixel_height) + ")");
  }
  check(FT_Init_FreeType(&library_));
  const FT_Error error = FT_New_Memory_Face(library_, font.data.data(), static_cast<FT_Long>(font.data.size()), 0, &face_);
  if (error == 0) {
    const FT_Error size_error = FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(font.pixel_height));
    if (size_error == 0) {
      ascender_ = static_cast<int>((face_->size->metrics.ascender + 63) >> 6);
      descender_ = static_cast<int>((-face_->size->metrics.descender + 63) >> 6);
      return;
    }
    FT_Done_Face(face_);
    FT_Done_FreeType(library_);
    check(size_error);
  }
  FT_Done_FreeType(library_);
  check(error);
}

TextRenderer::~TextRenderer() {
  FT_Done_Face(face_);
  FT_Done_FreeType(library_);
}

int TextRenderer::width(const std::string& text) {
  FT_Pos pen = 0;  // 26.6 fixed point
  for (const char32_t cp : decode_utf8(text)) {
    if (FT_Load_Char(face_, cp, FT_LOAD_DEFAULT) == 0) pen += face_->glyph->advance.x;
  }
  return static_cast<int>((pen + 63) >> 6);
}

std::string TextRenderer::fit(const std::string& text, int max_width) {
  if (width(text) <= max_width) return text;
  // The longest prefix whose advances, with those of "...", fit: each glyph measured once
  // (re-measuring every shorter prefix took 24 s for a 5,000-character title).
  const std::vector<char32_t> cps = decode_utf8(text);
  auto advance = [&](char32_t cp) -> FT_Pos {
    return FT_Load_Char(face_, cp, FT_LOAD_DEFAULT) == 0 ? face_->glyph->advance.x : 0;
  };
  const FT_Pos dots = 3 * advance(U'.');  // 26.6 fixed point, as width()
  std::size_t kept = 0;
  for (FT_Pos pen = dots; kept < cps.size(); ++kept) {
    pen += advance(cps[kept]);
    if (static_cast<int>((pen + 63) >> 6) > max_width) break;
  }
  if (kept == cps.size()) kept = cps.size() - 1;  // the whole text did not fit without dots
  if (static_cast<int>((dots + 63) >> 6) > max_width) return "";
  std::string shortened;
  for (std::size_t k = 0; k < kept; ++k) {  // re-encode as UTF-8
    const char32_t cp = cps[k];
    if (cp < 0x80) {
      shortened += static_cast<char>(cp);
    } else if (cp < 0x800) {
      shortened += static_cast<char>(0xC0 | (cp >> 6));
      shortened += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      shortened += static_cast<char>(0xE0 | (cp >> 12));
      shortened += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      shortened += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      shortened += static_cast<char>(0xF0 | (cp >> 18));
      shortened += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      shortened += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      shortened += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }
  return shortened + "...";
}

void TextRenderer::draw(Image& image, int x, int baseline, const std::string& text, Color color) {
  const std::uint8_t ink[3] = {static_cast<std::uint8_t>(std::lround(255 * std::clamp(color.r, 0.0f, 1.0f))),
                               static_cast<std::uint8_t>(std::lround(255 * std::clamp(color.g, 0.0f, 1.0f))),
                               static_cast<std::uint8_t>(std::lround(255 * std::clamp(color.b, 0.0f, 1.0f)))};
  FT_Pos pen = static_cast<FT_Pos>(x) * 64;
  for (const char32_t cp : decode_utf8(text)) {
    if (FT_Load_Char(face_, cp, FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot glyph = face_->glyph;
    const FT_Bitmap& bitmap = glyph->bitmap;
    const int left = static_cast<int>((pen + 32) >> 6) + glyph->bitmap_left;
    const int top = baseline - glyph->bitmap_top;
    for (unsigned row = 0; row < bitmap.rows; ++row) {
      const int py = top + static_cast<int>(row);
      if (py < 0 || py >= image.height) continue;
      for (unsigned col = 0; col < bitmap.width; ++col) {
        const int px = left + static_cast<int>(col);
        if (px < 0 || px >= image.width) continue;
        const unsigned coverage = bitmap.buffer[row * bitmap.pitch + col];
        if (coverage == 0) continue;
        std::uint8_t* pixel = &image.rgb[(static_cast<std::size_t>(py) * image.width + px) * 3];
        for (int k = 0; k < 3; ++k)
          pixel[k] = static_cast<std::uint8_t>((pixel[k] * (255 - coverage) + ink[k] * coverage + 127) / 255);
      }
    }
    pen += glyph->advance.x;
  }
}

}  // namespace envcrust::render::detail
