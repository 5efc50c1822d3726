// Fixture of the CLI tests: a fresh folder per test under the system temp directory.
#pragma once

#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <unistd.h>
#include <string>

namespace envcrust::testing {

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Suite, test and process in the name: two suites' tests of one name, or two test runs at
    // once (a CI clone beside a local run), never share or remove each other's folder.
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "envcrust_cli_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
                       std::to_string(::getpid());
    std::replace(name.begin(), name.end(), '/', '_');  // parameterized tests: "Suite/Test.case/3"
    dir_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }
  /// `envcrust reconstruct FILE -o x.ply` (both in the test folder) exits with 1 and the one
  /// line "envcrust: error: FILE: problem", and writes no output.
  void expect_reconstruct_refuses(const std::string& file, const std::string& problem) const {
    const CommandResult r = run_envcrust("reconstruct " + path(file) + " -o " + path("x.ply"));
    EXPECT_EQ(r.exit_code, 1) << file;
    EXPECT_EQ(r.err, "envcrust: error: " + path(file) + ": " + problem + "\n");
    EXPECT_FALSE(std::filesystem::exists(path("x.ply"))) << file;
  }
  std::filesystem::path dir_;
};

/// Runs `envcrust args` (which should ask for --json) and parses its output; a non-zero exit
/// is a test failure (naming the command and its stderr) and gives an empty object.
inline nlohmann::json run_envcrust_json(const std::string& args) {
  const CommandResult r = run_envcrust(args);
  if (r.exit_code != 0) {
    ADD_FAILURE() << "envcrust " << args << " exited with " << r.exit_code << ": " << r.err;
    return nlohmann::json::object();
  }
  return nlohmann::json::parse(r.out);
}

}  // namespace envcrust::testing
