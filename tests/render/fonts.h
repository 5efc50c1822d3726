// The caption font of the tests (DejaVu Sans from fonts-dejavu-core), when installed.
#pragma once

#include "envcrust/io.h"
#include "envcrust/render.h"

#include <filesystem>
#include <optional>

namespace envcrust::render::testing {

inline constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

inline std::optional<Font> test_font() {
  if (!std::filesystem::exists(kFontPath)) return std::nullopt;
  return Font{io::read_binary_file(kFontPath)};
}

}  // namespace envcrust::render::testing
