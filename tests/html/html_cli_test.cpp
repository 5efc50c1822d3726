// envcrust reconstruct/analyze --html through the program: the page's data match the mesh
// written, and the option's refusals come before the run, in one line.
#include "cli/run_command.h"
#include "html/page_reader.h"

#include "envcrust/io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace envcrust::testing {
namespace {

namespace fs = std::filesystem;

class HtmlOption : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("envcrust_html_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

bool skipped_without_three(const CommandResult& run) {
  return run.err.find("built without three.js") != std::string::npos;
}

TEST_F(HtmlOption, reconstruct_page_holds_the_written_mesh_and_its_distances) {
  const auto run = run_envcrust("reconstruct builtin:cylinder -n 2000 --seed 1 -q -o " + path("c.ply") + " --html " +
                                path("c.html"));
  if (skipped_without_three(run)) GTEST_SKIP() << run.err;
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string page = slurp(path("c.html"));
  EXPECT_GT(page.size(), 10'000u);
  const TriangleMesh mesh = io::read_triangle_mesh(path("c.ply"));
  const auto info = nlohmann::json::parse(script_text(page, "mesh-info"));
  EXPECT_EQ(info["vertices"], mesh.vertices.size());
  EXPECT_EQ(info["faces"], mesh.triangles.size());
  EXPECT_EQ(info["loops"].size(), 2u);  // the open cylinder's two rims
  EXPECT_EQ(decode_block<float>(page, "data-positions").size(), 3 * mesh.vertices.size());
  EXPECT_EQ(decode_block<std::uint32_t>(page, "data-faces").size(), 3 * mesh.triangles.size());
  const auto distances = decode_block<float>(page, "data-distances");
  ASSERT_EQ(distances.size(), mesh.vertices.size());
  // The sheet lies among the samples: no vertex is farther from them than a few spacings.
  for (const float d : distances) EXPECT_LT(d, 0.2f);
  EXPECT_NE(page.find("Its shape is that of an annulus (a tube open at both ends)."), std::string::npos);
  EXPECT_NE(page.find("<tr><td>input_points</td><td>2000</td></tr>"), std::string::npos);
}

TEST_F(HtmlOption, analyze_colours_by_the_reference_only_when_one_is_given) {
  std::ofstream(path("tri.off")) << "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  std::ofstream(path("ref.xyz")) << "0 0 1\n10 10 1\n";  // one point alone frames nothing
  auto run = run_envcrust("analyze " + path("tri.off") + " -q --html " + path("plain.html"));
  if (skipped_without_three(run)) GTEST_SKIP() << run.err;
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string plain = slurp(path("plain.html"));
  EXPECT_EQ(script_text(plain, "data-distances"), "");
  EXPECT_NE(plain.find("no --reference was given to measure distances to"), std::string::npos);
  run = run_envcrust("analyze " + path("tri.off") + " -q --reference " + path("ref.xyz") + " --html " +
                     path("ref.html"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto distances = decode_block<float>(slurp(path("ref.html")), "data-distances");
  ASSERT_EQ(distances.size(), 4u);
  EXPECT_NEAR(distances[0], 1.0, 1e-6);
  EXPECT_NEAR(distances[2], std::sqrt(3.0), 1e-6);
}

TEST_F(HtmlOption, refusals_come_before_the_run_in_one_line) {
  auto run = run_envcrust("reconstruct builtin:cylinder -n 2000 -q -o " + path("c.ply") + " --html " +
                          path("missing/c.html"));
  if (skipped_without_three(run)) GTEST_SKIP() << run.err;
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "envcrust: error: " + path("missing/c.html") + ": folder '" + path("missing") + "' does not exist\n");
  EXPECT_FALSE(fs::exists(path("c.ply")));

  run = run_envcrust("reconstruct builtin:cylinder -n 2000 -q -o " + path("c.ply") + " --report " + path("r") +
                     " --html " + path("r"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "envcrust: usage error: --report and --html name the same file '" + path("r") + "'\n");

  std::ofstream(path("loop.polyline")) << "0 0 0\n1 0 0\n0 1 0\n";
  run = run_envcrust("analyze --curve " + path("loop.polyline") + " --html " + path("l.html"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "envcrust: usage error: analyze: --html shows a MESH, not a --curve\n");
  EXPECT_FALSE(fs::exists(path("l.html")));
}

}  // namespace
}  // namespace envcrust::testing
