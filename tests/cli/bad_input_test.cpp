// Bad input files through the binary: every reader's refusal reaches the user as one line
// "envcrust: error: FILE[:LINE]: problem", exit code 1, and no output file.
#include "cli_fixture.h"
#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

using envcrust::testing::CliTest;
using envcrust::testing::run_envcrust;
using envcrust::testing::run_envcrust_json;

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
      {"a.foo", "0 0 0\n", ": unknown extension '.foo' (expected .xyz, .pts, .txt, .csv, .ply, .off, .obj, .stl, .las)"},
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
      {"points.xyz", "0 0 0\n", ": a point file, not a mesh: analyze reads meshes (.ply, .off, .obj, .stl); "
                                "reconstruct it first, or give it as --reference, or as --curve if it is an ordered "
                                "closed curve"},
      {"points.foo", "0 0 0\n", ": unknown extension '.foo' (expected .off, .obj, .ply, .stl)"},
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

namespace {

// A sphere of 400 points (a Fibonacci lattice; z from 0.9975 down) scaled by `scale` and moved by `offset`.
void write_sphere(const std::string& file, double scale, double offset) {
  std::ofstream f(file);
  f.precision(17);
  for (int i = 0; i < 400; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / 400.0, r = std::sqrt(1.0 - z * z), a = 2.399963229728653 * i;
    f << offset + scale * r * std::cos(a) << " " << offset + scale * r * std::sin(a) << " " << offset + scale * z
      << "\n";
  }
}

}  // namespace

// Coordinates the geometry cannot hold (squares of squared radii overflow beyond about 1e77,
// underflow below 1e-77; a sphere of radius 1e-200 once read as a line; a unit sphere 1e12 from the origin keeps 4 digits) are refused by
// name before any stage runs: the Power Crust crashed on the first two.
TEST_F(CliTest, coordinates_too_large_too_small_or_too_far_out_are_refused) {
  write_sphere(path("big.xyz"), 1e100, 0.0);
  write_sphere(path("small.xyz"), 1e-150, 0.0);
  write_sphere(path("tiny.xyz"), 1e-200, 0.0);  // its squared extent underflows to 0
  write_sphere(path("far.xyz"), 1.0, 1e12);
  const std::pair<const char*, const char*> cases[] = {
      {"big.xyz", ":1: coordinate beyond 1e30 in magnitude: scale the input down"},  // found by the reader
      {"small.xyz", ": the points span only 3.45e-150 (bounding-box diagonal), below 1e-30: scale the input up"},
      {"tiny.xyz", ": the points span only 3.45e-200 (bounding-box diagonal), below 1e-30: scale the input up"},
      {"far.xyz", ": the points span only 3.46 at coordinates up to 1e+12: too few digits are left to tell them "
                  "apart; move the input near the origin"},
  };
  for (const auto& [name, problem] : cases) {
    for (const char* command : {"powercrust", "reconstruct"}) {
      const auto r = run_envcrust(std::string(command) + " " + path(name) + " -o " + path("out.ply"));
      EXPECT_EQ(r.exit_code, 1) << command << " " << name;
      EXPECT_EQ(r.err, "envcrust: error: " + path(name) + problem + "\n") << command;
      EXPECT_FALSE(std::filesystem::exists(path("out.ply"))) << command << " " << name;
    }
  }
}

// A run that fails after its stages (an unreadable reference, a report path that is a
// folder) writes none of its outputs, and two outputs naming one file are refused up front.
TEST_F(CliTest, failed_runs_leave_no_outputs_and_outputs_must_differ) {
  write_sphere(path("s.xyz"), 1.0, 0.0);
  const std::string out = path("out.ply");
  auto r = run_envcrust("reconstruct " + path("s.xyz") + " -o " + out + " -r " + path("none.off"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("none.off") + ": cannot open file\n");
  EXPECT_FALSE(std::filesystem::exists(out));

  std::filesystem::create_directories(path("r.json"));
  r = run_envcrust("reconstruct " + path("s.xyz") + " -o " + out + " --report " + path("r.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("r.json") + ": is a folder, not a file\n");
  EXPECT_FALSE(std::filesystem::exists(out));

  r = run_envcrust("reconstruct " + path("s.xyz") + " -o " + out + " --envelope-out " + path(".") + "/out.ply");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "envcrust: usage error: -o and --envelope-out name the same file '" + path(".") + "/out.ply'\n");
  EXPECT_FALSE(std::filesystem::exists(out));

  r = run_envcrust("sample trefoil-ribbon -n 100 -o " + path("m.xyz") + " --boundary-out " + path("b.off"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("b.off") + ": unknown extension '.off' (expected .polyline, .xyz)\n");
  EXPECT_FALSE(std::filesystem::exists(path("m.xyz")));

  r = run_envcrust("envelope " + path("s.xyz") + " --rho 1e9 -o " + path("e.xyz"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: " + path("s.xyz") + ": the envelope has no samples: rho 1e+09 is more "
                        "than a quarter of the input's size", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(path("e.xyz")));

  std::ofstream(path("file")) << "x\n";
  r = run_envcrust("experiment cylinder --quick --no-figures -o " + path("file"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: " + path("file") + ": cannot make the output folder (", 0), 0u) << r.err;
}

// Counts and ranges are checked when parsed, naming the flag; a file name that is not UTF-8
// still gives valid JSON (the bytes replaced).
TEST_F(CliTest, flags_out_of_range_name_the_flag_and_json_survives_any_file_name) {
  const std::pair<std::string, std::string> cases[] = {
      {"sample sphere -n 1000000000000 -o " + path("s.xyz"),
       "--count: must be a whole number in 1..100000000 (got '1000000000000')"},
      {"reconstruct builtin:cylinder --spacing 0 -o " + path("c.ply"), "--spacing: must be a number in (0, 4] (got '0')"},
      {"reconstruct builtin:cylinder --rho-gap-quantile nan -o " + path("c.ply"),
       "--rho-gap-quantile: must be a number in [0, 1] (got 'nan')"},
      {"reconstruct builtin:cylinder --rho-width-cap 0 -o " + path("c.ply"),
       "--rho-width-cap: must be a number > 0 (got '0')"},
      {"reconstruct builtin:cylinder --remesh --remesh-iterations 0 -o " + path("c.ply"),
       "--remesh-iterations: must be a whole number in 1..100 (got '0')"},
      {"powercrust builtin:sphere --box-scale 1e12 -o " + path("c.ply"),
       "--box-scale: must be a number in (1, 1000] (got '1e12')"},
      {"reconstruct builtin:cylinder --rho inf -o " + path("c.ply"), "--rho must be 'auto' or a positive number (got 'inf')"},
      // CLI11 alone wrapped -1 to 2^64 - 1 and saturated a seed beyond 64 bits.
      {"sample sphere --seed -1 -o " + path("s.xyz"),
       "--seed: must be a whole number from 0 to 18446744073709551615 (got '-1')"},
      {"analyze " + path("s.xyz") + " --knot-seed 99999999999999999999",
       "--knot-seed: must be a whole number from 0 to 18446744073709551615 (got '99999999999999999999')"},
  };
  for (const auto& [args, problem] : cases) {
    const auto r = run_envcrust(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, "envcrust: usage error: " + problem + "\n") << args;
  }
  const std::string odd = path("bad\xff\xfe.xyz");
  write_sphere(odd, 1.0, 0.0);
  const auto j = run_envcrust_json("powercrust '" + odd + "' -o " + path("c.ply") + " --json");
  EXPECT_EQ(j["input"], path("bad\xEF\xBF\xBD\xEF\xBF\xBD.xyz"));
  EXPECT_TRUE(std::filesystem::exists(path("c.ply")));
}
