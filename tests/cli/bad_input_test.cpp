// Bad input files through the binary: every reader's refusal reaches the user as one line
// "envcrust: error: FILE[:LINE]: problem", exit code 1, and no output file.
#include "cli_fixture.h"
#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

using envcrust::testing::CliTest;
using envcrust::testing::run_envcrust;

namespace {

struct BadFile {
  const char* name;
  std::string bytes;  // the file's content; "<absent>": the file is not created
  const char* problem;
};

// A 3-vertex binary PLY whose body stops after 6 of its 36 bytes.
std::string truncated_ply() {
  return std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                     "property float z\nend_header\n") +
         std::string(6, '\0');
}

class BadInputFile : public CliTest {
 protected:
  // `envcrust COMMAND FILE [-o out.ply]` exits 1 with exactly "envcrust: error: FILE<problem>"
  // and writes no out.ply.
  void expect_refused(const std::string& command, const BadFile& bad, bool has_output = true) {
    const std::string file = path(bad.name);
    if (bad.bytes != "<absent>") std::ofstream(file, std::ios::binary) << bad.bytes;
    const auto r = run_envcrust(command + " " + file + (has_output ? " -o " + path("out.ply") : std::string()));
    EXPECT_EQ(r.exit_code, 1) << bad.name;
    EXPECT_EQ(r.err, "envcrust: error: " + file + bad.problem + "\n") << bad.name;
    EXPECT_FALSE(std::filesystem::exists(path("out.ply"))) << bad.name;
  }
};

}  // namespace

TEST_F(BadInputFile, every_point_reader_refusal_is_one_line_naming_the_file_and_exit_1) {
  const BadFile cases[] = {
      {"none.xyz", "<absent>", ": cannot open file"},
      {"a.foo", "0 0 0\n", ": unknown extension '.foo' (expected .xyz, .pts, .txt, .ply, .off, .obj, .stl)"},
      {"trunc.ply", truncated_ply(), ": truncated binary data (vertex 0 of 3)"},
      {"nan.xyz", "0 0 0\n1 nan 0\n", ":2: non-finite coordinate"},
      {"inf.pts", "0 0 0\n1 inf 0\n", ":2: non-finite coordinate"},
      {"cols.xyz", "0 0 0\n1 2\n", ":2: expected 3 numbers (as on line 1), got 2"},
      {"empty.txt", "# only a comment\n\n", ": no points"},
      {"trunc.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", ": unexpected end of file (vertex 2 of 3)"},
  };
  for (const auto& bad : cases) {
    expect_refused("powercrust", bad);
    expect_refused("reconstruct", bad);
  }
}

TEST_F(BadInputFile, analyze_refuses_point_files_and_broken_meshes_by_name) {
  const BadFile cases[] = {
      {"none.off", "<absent>", ": cannot open file"},
      {"points.xyz", "0 0 0\n", ": unknown extension '.xyz' (expected .off, .obj, .ply, .stl)"},
      {"trunc.ply", truncated_ply(), ": truncated binary data (vertex 0 of 3)"},
      {"trunc.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", ": unexpected end of file (vertex 2 of 3)"},
  };
  for (const auto& bad : cases) expect_refused("analyze", bad, false);
}

TEST_F(CliTest, analyze_curve_that_no_projection_resolves_names_the_file) {
  // A triangle traced twice, 1e-7 apart: every projection has (nearly) coincident crossings.
  {
    std::ofstream f(path("back.polyline"));
    f << "0 0 0\n1 0 0\n1 1 0\n0 0 0.0000001\n1 0 0.0000001\n1 1 0.0000001\n";
  }
  const auto r = run_envcrust("analyze --curve " + path("back.polyline"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: " + path("back.polyline") + ": no generic projection found", 0), 0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

TEST_F(CliTest, analyze_prints_faces_not_oriented_alike_and_welded_vertices) {
  // Two triangles sharing the edge 1-2 once vertex 4 (a copy of 2) is welded, the second flipped.
  {
    std::ofstream f(path("flip.off"));
    f << "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 1 0\n3 0 1 2\n3 1 4 3\n";
  }
  const auto r = run_envcrust("analyze " + path("flip.off"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  faces not oriented alike: 1 edges that both their faces run the same way\n"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  1 vertices welded to another at the same position"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(run_envcrust("analyze " + path("flip.off") + " --json").out);
  EXPECT_EQ(j["misoriented_edges"], 1);
  EXPECT_EQ(j["welded_vertices"], 1);
}

TEST_F(CliTest, sample_mesh_refuses_point_sampling_flags) {
  for (const char* flag : {"-n 5", "--noise 0.1", "--seed 3", "--normals"}) {
    const auto r = run_envcrust(std::string("sample sphere --mesh ") + flag + " -o " + path("s.ply"));
    EXPECT_EQ(r.exit_code, 2) << flag;
    EXPECT_NE(r.err.find("excludes"), std::string::npos) << flag << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(path("s.ply"))) << flag;
  }
}

TEST_F(CliTest, powercrust_poles_ply_is_read_back_by_render_balls) {
  const auto r = run_envcrust("powercrust builtin:sphere -n 2000 -q -o " + path("c.ply") + " --poles " +
                              path("poles.ply"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto image = run_envcrust("render " + path("c.ply") + " --balls " + path("poles.ply") + " -o " + path("b.png") + " --size 64x64");
  EXPECT_EQ(image.exit_code, 0) << image.err;
  EXPECT_TRUE(std::filesystem::exists(path("b.png")));
}
