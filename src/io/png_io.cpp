// PNG files through libpng's simplified API (no setjmp error handling needed).
#include "envcrust/io.h"

#include "io_detail.h"

#include <png.h>

#include <ostream>

namespace envcrust::io {

void write_png(const std::filesystem::path& path, const render::Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    detail::fail(path, "cannot write an image of " + std::to_string(image.width) + " x " +
                           std::to_string(image.height) + " pixels from " +
                           std::to_string(image.rgb.size()) + " bytes");
  }
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  // The first call measures, the second encodes into the buffer.
  if (png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0, nullptr) == 0) {
    detail::fail(path, std::string("PNG encoding failed (") + png.message + ")");
  }
  std::string bytes(size, '\0');
  if (png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr) == 0) {
    detail::fail(path, std::string("PNG encoding failed (") + png.message + ")");
  }
  bytes.resize(size);
  write_atomic(path, true, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

render::Image read_png(const std::filesystem::path& path) {
  const std::string bytes = detail::read_file(path);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()) == 0) {
    detail::fail(path, std::string("not a PNG file (") + png.message + ")");
  }
  png.format = PNG_FORMAT_RGB;
  render::Image image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  const png_color black{0, 0, 0};
  if (png_image_finish_read(&png, &black, image.rgb.data(), 0, nullptr) == 0) {
    detail::fail(path, std::string("corrupt PNG data (") + png.message + ")");
  }
  return image;
}

}  // namespace envcrust::io
