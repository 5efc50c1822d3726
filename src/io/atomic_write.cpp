// Atomic file writing: fill a temp file next to the target, then rename it onto the target.
#include "envcrust/io.h"

#include "io_detail.h"

#include <cerrno>
#include <fstream>
#include <initializer_list>
#include <random>
#include <system_error>

namespace envcrust::io {

namespace {

std::filesystem::path temp_path_for(const std::filesystem::path& path) {
  // A hidden name in the same folder: rename() is only atomic within one file system.
  std::random_device random;
  std::uniform_int_distribution<unsigned> hex_digit(0, 15);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string suffix;
    for (int i = 0; i < 8; ++i) {
      suffix += "0123456789abcdef"[hex_digit(random)];
    }
    // Appending (rather than operator+) avoids a GCC 12 -Wrestrict false positive.
    std::string name = ".";
    name.append(path.filename().string()).append(".").append(suffix).append(".tmp");
    auto candidate = path.parent_path() / name;
    std::error_code ec;
    if (!std::filesystem::exists(candidate, ec)) {
      return candidate;
    }
  }
  detail::fail(path, "cannot find a free temporary file name");
}

void remove_quietly(const std::filesystem::path& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

}  // namespace

void write_atomic(const std::filesystem::path& path, bool binary,
                  const std::function<void(std::ostream&)>& fill) {
  if (path.filename().empty()) {
    detail::fail(path, "not a file name");
  }
  const std::filesystem::path temp = temp_path_for(path);
  std::ofstream out(temp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
  if (!out) {
    const int error = errno;
    detail::fail(path, "cannot create temporary file " + temp.string() + " (" +
                           std::generic_category().message(error) + ")");
  }
  try {
    fill(out);
  } catch (...) {
    out.close();
    remove_quietly(temp);
    throw;
  }
  out.flush();
  const bool written = static_cast<bool>(out);
  out.close();
  if (!written || out.fail()) {
    remove_quietly(temp);
    detail::fail(path, "write failed (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    remove_quietly(temp);
    detail::fail(path, "cannot replace file (" + ec.message() + ")");
  }
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  write_atomic(path, false, [&](std::ostream& out) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

void check_output_path(const std::filesystem::path& path, OutputKind kind) {
  if (path.filename().empty()) {
    detail::fail(path, "not a file name");
  }
  const std::string extension = extension_of(path);
  auto expect = [&](std::initializer_list<const char*> known, const char* listed) {
    for (const char* k : known)
      if (extension == k) return;
    detail::unknown_extension(path, listed);
  };
  switch (kind) {
    case OutputKind::Mesh: expect({"ply", "off", "obj"}, ".ply, .off, .obj"); break;
    case OutputKind::Points: expect({"xyz", "ply"}, ".xyz, .ply"); break;
    case OutputKind::Image: expect({"png"}, ".png"); break;
    case OutputKind::Polyline: expect({"polyline", "xyz"}, ".polyline, .xyz"); break;
    case OutputKind::Text: break;
  }
  const std::filesystem::path folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    detail::fail(path, "folder '" + folder.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(path, ec)) detail::fail(path, "is a folder, not a file");
}

}  // namespace envcrust::io
