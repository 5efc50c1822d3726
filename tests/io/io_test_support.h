// Shared helpers of the io tests: a self-cleaning temp folder, file builders, error capture.
#pragma once

#include "envcrust/errors.h"
#include "envcrust/types.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <string_view>

namespace envcrust::io::testing {

/// Fixture owning a fresh folder under the system temp directory, removed after the test.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::random_device random;
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("envcrust_io_") + info->test_suite_name() + "_" + info->name() + "_" +
            std::to_string(random()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }

  [[nodiscard]] std::filesystem::path path(const std::string& name) const { return dir_ / name; }

  /// Write `bytes` to `name` in the temp folder and return its path.
  std::filesystem::path write(const std::string& name, std::string_view bytes) const {
    const auto file = path(name);
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return file;
  }

  /// Names of the files in the temp folder.
  [[nodiscard]] std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  std::filesystem::path dir_;
};

/// The message of the IoError thrown by `action`, or a description of what happened instead.
template <class Action>
std::string io_error_of(Action&& action) {
  try {
    action();
  } catch (const IoError& error) {
    return error.what();
  } catch (const std::exception& error) {
    return std::string("unexpected exception: ") + error.what();
  }
  return "no exception";
}

/// Run `action` (`reader` reading `file`): success, or an IoError of one line "FILE: problem";
/// anything else fails the test (the project's rule for bad input).
template <class Action>
void expect_read_or_one_line_refusal(const std::filesystem::path& file, const char* reader, Action&& action) {
  try {
    action();
  } catch (const IoError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(file.string() + ":", 0), 0U) << reader << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << reader << ": " << message;
  } catch (const std::exception& error) {
    ADD_FAILURE() << reader << " threw a non-IoError: " << error.what();
  }
}

/// Builds binary file contents value by value in a chosen byte order.
class Bytes {
 public:
  explicit Bytes(bool big_endian = false) : big_endian_(big_endian) {}
  Bytes& text(std::string_view text) {
    data_.append(text);
    return *this;
  }
  template <class T>
  Bytes& put(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (big_endian_ != (std::endian::native == std::endian::big)) {
      std::reverse(bytes, bytes + sizeof(T));
    }
    data_.append(bytes, sizeof(T));
    return *this;
  }
  [[nodiscard]] const std::string& str() const { return data_; }

 private:
  bool big_endian_;
  std::string data_;
};

inline void expect_same_point(const Point3& expected, const Point3& actual) {
  EXPECT_EQ(expected.x(), actual.x());
  EXPECT_EQ(expected.y(), actual.y());
  EXPECT_EQ(expected.z(), actual.z());
}

}  // namespace envcrust::io::testing
