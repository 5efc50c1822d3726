// Atomic file writing: fill a temp file next to the target, then rename it onto the target.
#include "envcrust/io.h"

#include "io_detail.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
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

// The temporary files being filled, for remove_pending_temp_files() (called from a signal
// handler: fixed storage, atomic flags, no allocation).
constexpr std::size_t kPendingSlots = 16;
constexpr std::size_t kPendingPathBytes = 4096;
struct PendingSlot {
  std::atomic<bool> used{false};
  std::atomic<bool> ready{false};
  std::array<char, kPendingPathBytes> path{};
};
std::array<PendingSlot, kPendingSlots> pending;

// Registers `temp` while it exists; a path too long or a full table goes unregistered (the
// file is still removed on every error, only not on a signal).
class PendingTemp {
 public:
  explicit PendingTemp(const std::filesystem::path& temp) {
    const std::string text = temp.string();
    if (text.size() >= kPendingPathBytes) return;
    for (auto& slot : pending) {
      bool expected = false;
      if (slot.used.compare_exchange_strong(expected, true)) {
        std::memcpy(slot.path.data(), text.c_str(), text.size() + 1);
        slot.ready.store(true);
        slot_ = &slot;
        return;
      }
    }
  }
  ~PendingTemp() {
    if (!slot_) return;
    slot_->ready.store(false);
    slot_->used.store(false);
  }
  PendingTemp(const PendingTemp&) = delete;
  PendingTemp& operator=(const PendingTemp&) = delete;

 private:
  PendingSlot* slot_ = nullptr;
};

// The file an output path names: a symbolic link's target (the link stays), which must be a
// regular file if it exists (renaming onto /dev/null or a pipe would replace the device).
std::filesystem::path resolve_target(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::path target = path;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec))) {
    target = std::filesystem::weakly_canonical(path, ec);
    if (ec) detail::fail(path, "cannot follow the symbolic link (" + ec.message() + ")");
  }
  const auto status = std::filesystem::status(target, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
      !std::filesystem::is_directory(status))
    detail::fail(path, "exists and is not a regular file (a device, pipe or socket): not replaced");
  return target;
}

}  // namespace

void remove_pending_temp_files() noexcept {
  for (auto& slot : pending)
    if (slot.ready.load()) ::unlink(slot.path.data());
}

void write_atomic(const std::filesystem::path& path, bool binary,
                  const std::function<void(std::ostream&)>& fill) {
  if (path.filename().empty()) {
    detail::fail(path, "not a file name");
  }
  const std::filesystem::path target = resolve_target(path);
  const std::filesystem::path temp = temp_path_for(target);
  const PendingTemp registered(temp);
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
  std::filesystem::rename(temp, target, ec);
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
    case OutputKind::Mesh: expect({"ply", "off", "obj", "stl"}, ".ply, .off, .obj, .stl"); break;
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
  (void)resolve_target(path);
  // Found now rather than after the run (root may write anywhere: access() says so).
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    detail::fail(path, "folder '" + folder.string() + "' is not writable (" + std::generic_category().message(errno) + ")");
}

}  // namespace envcrust::io
