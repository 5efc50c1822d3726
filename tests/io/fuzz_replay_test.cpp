// Replays the fuzzers' seed corpora (fuzz/corpus/) and every input a fuzzer found to crash a
// reader (tests/io/fuzz_regressions/, docs/fuzzing.md): each is read or refused with one line.
#include "envcrust/io.h"
#include "io_test_support.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace envcrust::io {
namespace {

// Read `file` with every reader its extension reaches; anything but success or an IoError
// of one line "FILE: problem" fails the test.
void read_with_every_reader(const std::filesystem::path& file) {
  SCOPED_TRACE(file.string());
  const auto survive = [&](const char* reader, auto&& action) { testing::expect_read_or_one_line_refusal(file, reader, action); };
  if (is_nurbs_file(file)) {
    survive("read_nurbs_patches", [&] { read_nurbs_patches(file); });
    return;
  }
  survive("read_attributed_points", [&] { read_attributed_points(file); });
  survive("read_triangle_mesh", [&] { read_triangle_mesh(file); });
  survive("read_polyline", [&] { read_polyline(file); });
  survive("read_balls", [&] { read_balls(file); });
}

// The files under `folder`, sorted (an absent folder has none).
std::vector<std::filesystem::path> files_under(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(folder)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FuzzReplay, seed_corpora_are_read_or_refused_in_one_line) {
  const auto files = files_under(std::filesystem::path(ENVCRUST_SOURCE_DIR) / "fuzz" / "corpus");
  EXPECT_GE(files.size(), 11U);
  for (const auto& file : files) read_with_every_reader(file);
}

TEST(FuzzReplay, crashes_found_by_fuzzing_are_refused_in_one_line) {
  for (const auto& file : files_under(std::filesystem::path(ENVCRUST_SOURCE_DIR) / "tests" / "io" / "fuzz_regressions")) {
    read_with_every_reader(file);
  }
}

}  // namespace
}  // namespace envcrust::io
