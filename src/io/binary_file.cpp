// Whole files as bytes, for data the library parses itself (font files for captions).
#include "envcrust/io.h"

#include "io_detail.h"

namespace envcrust::io {

std::vector<std::uint8_t> read_binary_file(const std::filesystem::path& path) {
  const std::string data = detail::read_file(path);
  return {data.begin(), data.end()};
}

}  // namespace envcrust::io
