// End-to-end tests of `envcrust render`: PNG size, panels, balls, warnings and error messages.
#include "cli_fixture.h"
#include "envcrust/io.h"
#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

using envcrust::testing::CliTest;
using envcrust::testing::run_envcrust;
namespace fs = std::filesystem;

namespace {

/// Width and height from the PNG's IHDR chunk (bytes 16-23, big-endian).
std::pair<unsigned, unsigned> png_size(const std::string& file) {
  const auto bytes = envcrust::io::read_binary_file(file);
  if (bytes.size() < 24) return {0, 0};
  auto be32 = [&](std::size_t at) {
    return (unsigned(bytes[at]) << 24) | (unsigned(bytes[at + 1]) << 16) | (unsigned(bytes[at + 2]) << 8) | bytes[at + 3];
  };
  return {be32(16), be32(20)};
}

/// Pixels where channel `c` exceeds both others by 40 (a saturated colour).
int dominant_pixels(const envcrust::render::Image& image, int c) {
  int count = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    const int v = image.rgb[i + c], a = image.rgb[i + (c + 1) % 3], b = image.rgb[i + (c + 2) % 3];
    count += v > a + 40 && v > b + 40 ? 1 : 0;
  }
  return count;
}

TEST_F(CliTest, render_a_builtin_renders_at_the_requested_size_with_its_boundary_tubes) {
  const auto r = run_envcrust("render builtin:cylinder --size 160x120 -q -o " + path("c.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(png_size(path("c.png")), std::make_pair(160u, 120u));
  const auto image = envcrust::io::read_png(path("c.png"));
  EXPECT_GT(dominant_pixels(image, 1), 20);  // the first tube colour is green
}

TEST_F(CliTest, render_the_same_command_writes_the_same_bytes) {
  ASSERT_EQ(run_envcrust("render builtin:moebius --size 64x48 -q -o " + path("a.png")).exit_code, 0);
  ASSERT_EQ(run_envcrust("render builtin:moebius --size 64x48 -q -o " + path("b.png")).exit_code, 0);
  EXPECT_EQ(envcrust::io::read_binary_file(path("a.png")), envcrust::io::read_binary_file(path("b.png")));
}

// Panels of 80 x 60 in a 1 x 2 grid, gap 8, captions and title bands of 1.5 * 18 = 27 pixels.
TEST_F(CliTest, render_several_inputs_become_captioned_panels) {
  const auto r = run_envcrust("render builtin:sphere builtin:torus --size 80x60 --grid 1 2 --title T --json -o " +
                              path("g.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(png_size(path("g.png")), std::make_pair(8u + 2u * 88u, 8u + 27u + 60u + 27u + 8u));
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["panels"].size(), 2u);
  EXPECT_EQ(j["panels"][1]["caption"], "torus");
  EXPECT_GT(j["panels"][0]["triangles"].get<int>(), 100);
  EXPECT_EQ(j["panels"][0]["boundary_loops"], 0);
}

TEST_F(CliTest, render_a_point_file_with_balls_is_drawn) {
  {
    std::ofstream points(path("p.xyz"));
    for (int i = 0; i < 50; ++i) points << i * 0.02 << " 0 " << (i % 5) * 0.1 << "\n";
    std::ofstream balls(path("poles.txt"));
    balls << "# x y z radius label\n0.5 0 0.2 0.2 in\n0.5 0 0.2 5 out\n";
  }
  const auto r = run_envcrust("render " + path("p.xyz") + " --balls " + path("poles.txt") +
                              " --size 64x64 --json -o " + path("p.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["panels"][0]["points"], 50);
  EXPECT_EQ(j["panels"][0]["balls"], 1);  // the outer ball is left out by default
}

TEST_F(CliTest, render_a_missing_font_leaves_captions_out_with_a_warning) {
  const auto r = run_envcrust("render builtin:square --size 48x48 --caption sq --font " + path("none.ttf") +
                              " -q -o " + path("s.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "envcrust: warning: font " + path("none.ttf") + " not found: captions and title left out\n");
  EXPECT_EQ(png_size(path("s.png")), std::make_pair(8u + 48u + 8u, 8u + 48u + 27u + 8u));
}

// A file that is no font is an error naming it, for render and experiment alike, found
// before anything is drawn (the experiments ran first before, and the error named no file).
TEST_F(CliTest, a_font_freetype_cannot_use_is_an_error_naming_the_file) {
  {
    std::ofstream out(path("bad.ttf"));
    out << "not a font\n";
  }
  const std::string problem = path("bad.ttf") + ": render: cannot use the font (FreeType error ";
  const auto r = run_envcrust("render builtin:square --size 48x48 --caption sq --font " + path("bad.ttf") + " -o " +
                              path("s.png"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: " + problem, 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(path("s.png")));
  const auto e = run_envcrust("experiment cylinder --quick --font " + path("bad.ttf") + " -q -o " + path("exp"));
  EXPECT_EQ(e.exit_code, 1);
  EXPECT_EQ(e.err.rfind("envcrust: error: " + problem, 0), 0u) << e.err;
  EXPECT_FALSE(fs::exists(fs::path(path("exp")) / "cylinder"));
}

TEST_F(CliTest, render_bad_input_is_named_and_no_png_is_written) {
  const auto missing = run_envcrust("render " + path("missing.off") + " -o " + path("m.png"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err, "envcrust: error: " + path("missing.off") + ": cannot open file\n");
  {
    std::ofstream bad(path("bad.off"));
    bad << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n";
  }
  const auto bad = run_envcrust("render " + path("bad.off") + " -o " + path("m.png"));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find(path("bad.off") + ":"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(path("m.png")));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);  // bad.off, no temp file
}

// Points that all coincide frame nothing; as a reference they measure nothing (analyze).
TEST_F(CliTest, points_that_all_coincide_are_refused_by_render_and_as_a_reference) {
  {
    std::ofstream points(path("same.xyz"));
    for (int i = 0; i < 10; ++i) points << "1 2 3\n";
  }
  const std::string message = "envcrust: error: " + path("same.xyz") +
                              ": all its points coincide (a bounding box of no size: nothing to measure against or "
                              "to frame)\n";
  const auto r = run_envcrust("render " + path("same.xyz") + " -o " + path("s.png"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, message);
  EXPECT_FALSE(fs::exists(path("s.png")));
  const auto a = run_envcrust("analyze builtin:square --reference " + path("same.xyz"));
  EXPECT_EQ(a.exit_code, 1);
  EXPECT_EQ(a.err, message);
}

TEST_F(CliTest, render_an_empty_panel_is_refused_naming_the_input) {
  {
    std::ofstream points(path("p.xyz"));
    points << "0 0 0\n1 0 0\n0 1 0\n";
  }
  const auto r = run_envcrust("render " + path("p.xyz") + " --points-as none -o " + path("e.png"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("p.xyz") +
                       ": render: the scene is empty (no triangle, sphere or loop): nothing to draw\n");
}

TEST_F(CliTest, render_bad_size_and_view_are_usage_errors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"builtin:sphere --size 80", "--size: expected WIDTHxHEIGHT in pixels, e.g. 800x600, got '80'"},
      {"builtin:sphere --view side", "--view: expected iso, front, top or AZIMUTH,ELEVATION in degrees, got 'side'"},
      {"builtin:sphere --size 8x8", "--size: width and height must be in [16, 8192] pixels, got '8x8'"},
      {"builtin:sphere --view 30,200", "--view: the elevation must be in [-90, 90] degrees, got '30,200'"},
      {"builtin:sphere builtin:torus builtin:square --grid 1 2", "--grid 1 2: room for 2 panels, not the 3 inputs"},
      // A grid far larger than the inputs would be a canvas of empty panels (300,000 columns).
      {"builtin:sphere builtin:torus --grid 1 300000", "--grid 1 300000: leaves a row or column empty for 2 inputs"},
      {"builtin:sphere builtin:torus builtin:square --grid 3 2", "--grid 3 2: leaves a row or column empty for 3 inputs"},
  };
  for (const auto& [args, message] : cases) {
    const auto result = run_envcrust("render " + args + " -o " + path("x.png"));
    EXPECT_EQ(result.exit_code, 2) << args;
    EXPECT_EQ(result.err, "envcrust: usage error: " + message + "\n") << args;
  }
  EXPECT_FALSE(fs::exists(path("x.png")));
}

// An azimuth is an angle: one of 1e308 degrees is taken modulo a turn (it aborted the
// renderer before), and 370 degrees draws what 10 does.
TEST_F(CliTest, render_takes_the_azimuth_modulo_a_turn) {
  const auto huge = run_envcrust("render builtin:torus --size 64x48 --view 1e308,0 -o " + path("h.png"));
  ASSERT_EQ(huge.exit_code, 0) << huge.err;
  ASSERT_EQ(run_envcrust("render builtin:torus --size 64x48 --view 370,20 -o " + path("a.png")).exit_code, 0);
  ASSERT_EQ(run_envcrust("render builtin:torus --size 64x48 --view 10,20 -o " + path("b.png")).exit_code, 0);
  EXPECT_EQ(envcrust::io::read_binary_file(path("a.png")), envcrust::io::read_binary_file(path("b.png")));
}

}  // namespace

// --error-to colours a mesh by the distance of its vertices to a reference: the sphere's
// tessellation scaled by 1.1 lies 0.1 (plus the chords' sag) outside the original, so
// every vertex is at the top of the scale and the picture is red; the original against the
// scaled one, with red at 1, is blue. The report gives each panel's largest and mean error.
TEST_F(CliTest, render_error_to_colours_a_mesh_by_its_distance_to_a_reference) {
  ASSERT_EQ(run_envcrust("sample sphere --mesh -o " + path("s.ply")).exit_code, 0);
  envcrust::TriangleMesh larger = envcrust::io::read_triangle_mesh(path("s.ply"));
  for (auto& p : larger.vertices) p = envcrust::Point3(1.1 * p.x(), 1.1 * p.y(), 1.1 * p.z());
  envcrust::io::write_mesh(path("s11.off"), larger);

  const auto r = run_envcrust("render " + path("s11.off") + " --error-to " + path("s.ply") +
                              " --view front --size 96x96 --json -o " + path("e.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& error = j["panels"][0]["error"];
  EXPECT_NEAR(error["max"].get<double>(), 0.1, 0.01);
  EXPECT_NEAR(error["mean"].get<double>(), 0.1, 0.01);
  EXPECT_EQ(j["error_scale"]["red_at"].get<double>(), error["max"].get<double>());
  const auto red = envcrust::io::read_png(path("e.png"));
  EXPECT_GT(dominant_pixels(red, 0), 96 * 96 / 4);
  EXPECT_EQ(dominant_pixels(red, 2), 0);

  const auto b = run_envcrust("render " + path("s.ply") + " --error-to " + path("s11.off") +
                              " --error-max 1 --view front --size 96x96 -q -o " + path("b.png"));
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto blue = envcrust::io::read_png(path("b.png"));
  EXPECT_GT(dominant_pixels(blue, 2), 96 * 96 / 4);
  EXPECT_EQ(dominant_pixels(blue, 0), 0);

  const auto bad = run_envcrust("render " + path("s.ply") + " --error-max 1 -o " + path("x.png"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "envcrust: usage error: --error-max needs --error-to\n");
}
