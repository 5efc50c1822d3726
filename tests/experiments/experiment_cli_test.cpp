// `envcrust experiment`: listing, a quick run into a folder, and its usage errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/run_command.h"

namespace envcrust {
namespace {

using testing::run_envcrust;
using testing::slurp;

class ExperimentCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("envcrust_experiment_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(ExperimentCli, list_names_every_experiment_with_its_figures) {
  const auto r = run_envcrust("experiment --list");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("trefoil (Figures 1, 2): "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("unknot-radius (Figure 11): "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("density: "), std::string::npos) << r.out;
}

TEST_F(ExperimentCli, help_shows_the_defaults_and_the_common_flags) {
  const auto r = run_envcrust("experiment --help");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string flag : {"--quick", "--seed UINT=1", "--data-dir TEXT (Env:ENVCRUST_SHARED_DATA)",
                                 "--panel-width INT:INT in [16 - 8192]=320", "--json", "--quiet"})
    EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
}

// A panel size the figures cannot take fails when parsed, not after the experiments ran.
TEST_F(ExperimentCli, panel_sizes_are_checked_before_the_run) {
  const auto r = run_envcrust("experiment cylinder --quick --panel-width 0 -o " + dir_.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "envcrust: usage error: --panel-width: Value 0 not in range 16 to 8192\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "cylinder"));
}

TEST_F(ExperimentCli, quick_cylinder_writes_json_markdown_and_figures) {
  const auto r = run_envcrust("experiment cylinder --quick -q -o " + dir_.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(slurp(dir_ / "cylinder" / "results.json"));
  EXPECT_EQ(json["name"], "cylinder");
  const auto& table = json["tables"][0];
  std::size_t method = 0, loops = 0;
  for (std::size_t i = 0; i < table["columns"].size(); ++i) {
    if (table["columns"][i] == "method") method = i;
    if (table["columns"][i] == "loops") loops = i;
  }
  ASSERT_EQ(table["rows"].size(), 2u);
  EXPECT_EQ(table["rows"][0][method], "direct Power Crust");
  EXPECT_EQ(table["rows"][0][loops], 0);  // closed
  EXPECT_EQ(table["rows"][1][method], "envelope");
  EXPECT_EQ(table["rows"][1][loops], 2);
  ASSERT_EQ(json["figures"].size(), 2u);
  for (const auto& f : json["figures"]) {
    const auto png = dir_ / "cylinder" / f["file"].get<std::string>();
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
  }
  const std::string md = slurp(dir_ / "cylinder" / "results.md");
  EXPECT_NE(md.find("| method | ρ | envelope samples | topology ok |"), std::string::npos) << md;
  EXPECT_NE(md.find("![Open cylinder: direct Power Crust vs envelope](fig4_cylinder_results.png)"), std::string::npos);
}

TEST_F(ExperimentCli, scan_without_data_is_skipped_not_failed) {
  const auto r =
      run_envcrust("experiment scan --quick --json --data-dir " + (dir_ / "none").string() + " -o " + dir_.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["experiments"][0]["skipped"], true);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "scan" / "results.json"));
}

// No default folder: without --data-dir or ENVCRUST_SHARED_DATA the scan is skipped with a note
// saying how to give the data; the variable, when set, is the folder read.
TEST_F(ExperimentCli, scan_data_comes_from_the_flag_or_the_variable_only) {
  ::unsetenv("ENVCRUST_SHARED_DATA");
  auto r = run_envcrust("experiment scan --quick --no-figures --json -o " + dir_.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["experiments"][0]["skipped"], true);
  const std::string note = json["experiments"][0]["notes"][0];
  EXPECT_NE(note.find("--data-dir DIR or set ENVCRUST_SHARED_DATA=DIR"), std::string::npos) << note;

  // A points file that is not one: the error names the file under the variable's folder.
  const auto data = dir_ / "data";
  std::filesystem::create_directories(data / "foot_vhacd");
  std::ofstream(data / "foot_vhacd" / "points.xyz") << "not a point\n";
  ::setenv("ENVCRUST_SHARED_DATA", data.c_str(), 1);
  r = run_envcrust("experiment scan --quick --no-figures --scan-reference '' -q -o " + (dir_ / "out").string());
  ::unsetenv("ENVCRUST_SHARED_DATA");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find((data / "foot_vhacd" / "points.xyz").string()), std::string::npos) << r.err;
}

TEST_F(ExperimentCli, unknown_experiment_is_a_usage_error_naming_the_known_ones) {
  const auto r = run_envcrust("experiment nope -o " + dir_.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "envcrust: usage error: unknown experiment 'nope' (known: trefoil, cylinder, scan, paraboloid, cusp, "
            "normals, unknot-curve, unknot-radius, density, all)\n");
}

TEST_F(ExperimentCli, missing_output_folder_is_a_usage_error) {
  const auto r = run_envcrust("experiment cylinder");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "envcrust: usage error: experiment: -o DIR is required\n");
}

}  // namespace
}  // namespace envcrust
