// The HTML report in a real browser: headless Chromium opens pages that envcrust wrote, and
// the tests check the DOM after the scripts ran and the pixels of a screenshot. Skipped with a
// message when Chromium (Debian's chromium) is not installed or envcrust lacks three.js.
#include "cli/run_command.h"

#include "envcrust/io.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <unistd.h>

namespace envcrust::testing {
namespace {

namespace fs = std::filesystem;

std::string chromium_program() {
  for (const char* name : {"chromium", "chromium-browser"}) {
    if (std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0) return name;
  }
  return {};
}

class HtmlInChromium : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium_ = chromium_program();
    if (chromium_.empty()) GTEST_SKIP() << "chromium is not installed (Debian package chromium): browser tests skipped";
    dir_ = fs::temp_directory_path() / ("envcrust_html_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // Chromium's own profile per run: tests running side by side do not share one.
  std::string chromium_command(const std::string& action, const fs::path& page) const {
    return chromium_ + " --headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader --hide-scrollbars"
                       " --user-data-dir=" + (dir_ / "profile").string() +
           " --window-size=800,600 --virtual-time-budget=15000 " + action + " file://" + page.string();
  }

  std::string dom_of(const fs::path& page) const {
    const fs::path dom = dir_ / "dom.html";
    std::system((chromium_command("--dump-dom", page) + " >" + dom.string() + " 2>/dev/null").c_str());
    return slurp(dom);
  }

  render::Image screenshot_of(const fs::path& page) const {
    const fs::path png = dir_ / "shot.png";
    fs::remove(png);
    std::system((chromium_command("--screenshot=" + png.string(), page) + " >/dev/null 2>&1").c_str());
    if (!fs::exists(png)) ADD_FAILURE() << "chromium wrote no screenshot of " << page;
    return fs::exists(png) ? io::read_png(png) : render::Image{};
  }

  std::string chromium_;
  fs::path dir_;
};

// Pixels of the 3D view (the left 60% of the window, away from its toolbar and keys) that are
// not the white background, and how many colours they take.
struct ViewPixels {
  std::size_t coloured = 0, total = 0;
  std::set<int> colours;
};

ViewPixels view_pixels(const render::Image& image) {
  ViewPixels result;
  for (int y = image.height / 10; y < image.height * 85 / 100; ++y) {
    for (int x = image.width / 20; x < image.width * 55 / 100; ++x) {
      const auto* p = &image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x)];
      ++result.total;
      if (p[0] < 250 || p[1] < 250 || p[2] < 250) ++result.coloured;
      result.colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
    }
  }
  return result;
}

TEST_F(HtmlInChromium, reconstructed_moebius_band_renders_with_its_caption) {
  const fs::path page = dir_ / "moebius.html";
  const auto run = run_envcrust("reconstruct builtin:moebius -n 3000 --seed 1 -q -o " + (dir_ / "m.ply").string() +
                                " --html " + page.string());
  if (run.err.find("built without three.js") != std::string::npos) GTEST_SKIP() << run.err;
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_GT(fs::file_size(page), 10'000u);

  const std::string dom = dom_of(page);
  EXPECT_NE(dom.find("<body data-view=\"rendered\">"), std::string::npos) << dom.substr(0, 2000);
  EXPECT_NE(dom.find("envcrust reconstruct: builtin:moebius -&gt; "), std::string::npos);
  EXPECT_NE(dom.find("drag to turn it, scroll to zoom"), std::string::npos);
  EXPECT_NE(dom.find("Its shape is that of a Möbius band."), std::string::npos);
  EXPECT_NE(dom.find("<canvas data-engine=\"three.js"), std::string::npos);

  const ViewPixels view = view_pixels(screenshot_of(page));
  ASSERT_GT(view.total, 0u);
  // The band fills a good part of the view, shaded in many tones; a blank canvas is all white.
  EXPECT_GT(view.coloured, view.total / 10) << view.coloured << " of " << view.total << " pixels not white";
  EXPECT_GT(view.colours.size(), 50u);
}

TEST_F(HtmlInChromium, distance_colours_switched_on_change_the_view) {
  const fs::path page = dir_ / "moebius.html";
  const auto run = run_envcrust("reconstruct builtin:moebius -n 3000 --seed 1 -q -o " + (dir_ / "m.ply").string() +
                                " --html " + page.string());
  if (run.err.find("built without three.js") != std::string::npos) GTEST_SKIP() << run.err;
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path with_map = dir_ / "moebius_map.html";
  fs::copy_file(page, with_map);
  // '#distance' switches the map on at load, as a click on its box would.
  const auto plain = view_pixels(screenshot_of(page));
  const std::string command = chromium_command("--screenshot=" + (dir_ / "map.png").string(), with_map) + "#distance";
  std::system((command + " >/dev/null 2>&1").c_str());
  ASSERT_TRUE(fs::exists(dir_ / "map.png"));
  const auto map = view_pixels(io::read_png(dir_ / "map.png"));
  // The map's colours (viridis: violet to yellow) are not the band's grey-blue and terracotta.
  std::size_t new_colours = 0;
  for (const int c : map.colours) new_colours += plain.colours.count(c) == 0;
  EXPECT_GT(new_colours, map.colours.size() / 2);
}

TEST_F(HtmlInChromium, mesh_without_faces_gives_a_readable_page) {
  const fs::path mesh = dir_ / "empty.off";
  std::ofstream(mesh) << "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n";
  const fs::path page = dir_ / "empty.html";
  const auto run = run_envcrust("analyze " + mesh.string() + " --html " + page.string());
  if (run.err.find("built without three.js") != std::string::npos) GTEST_SKIP() << run.err;
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "envcrust: error: " + mesh.string() + ": no faces\n");
  ASSERT_TRUE(fs::exists(page)) << "no page for the broken mesh";

  const std::string dom = dom_of(page);
  EXPECT_NE(dom.find("<body data-view=\"rendered\">"), std::string::npos) << "its vertices are drawn as points";
  EXPECT_NE(dom.find("<p class=\"message\">" + mesh.string() + ": no faces</p>"), std::string::npos);
  EXPECT_NE(dom.find("The mesh could not be analyzed"), std::string::npos);
  const auto shot = screenshot_of(page);
  std::set<int> colours;
  for (std::size_t i = 0; i + 2 < shot.rgb.size(); i += 3)
    colours.insert((shot.rgb[i] << 16) | (shot.rgb[i + 1] << 8) | shot.rgb[i + 2]);
  EXPECT_GT(colours.size(), 10u) << "a blank page";
}

TEST_F(HtmlInChromium, empty_mesh_page_shows_its_message_in_the_view) {
  const fs::path mesh = dir_ / "nothing.off";
  std::ofstream(mesh) << "OFF\n0 0 0\n";
  const fs::path page = dir_ / "nothing.html";
  const auto run = run_envcrust("analyze " + mesh.string() + " --html " + page.string());
  if (run.err.find("built without three.js") != std::string::npos) GTEST_SKIP() << run.err;
  EXPECT_EQ(run.exit_code, 1);
  ASSERT_TRUE(fs::exists(page));
  const std::string dom = dom_of(page);
  EXPECT_NE(dom.find("<body data-view=\"empty\">"), std::string::npos) << dom.substr(0, 2000);
  EXPECT_NE(dom.find("Nothing to show in 3D: the mesh has no vertices."), std::string::npos);
  EXPECT_NE(dom.find("The mesh could not be analyzed"), std::string::npos);
}

TEST_F(HtmlInChromium, non_manifold_mesh_renders_and_says_so) {
  const fs::path mesh = dir_ / "book.off";
  std::ofstream(mesh) << "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 1 4\n";
  const fs::path page = dir_ / "book.html";
  const auto run = run_envcrust("analyze " + mesh.string() + " -q --html " + page.string());
  if (run.err.find("built without three.js") != std::string::npos) GTEST_SKIP() << run.err;
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string dom = dom_of(page);
  EXPECT_NE(dom.find("<body data-view=\"rendered\">"), std::string::npos);
  EXPECT_NE(dom.find("Not a 2-manifold: 1 non-manifold edges, 0 non-manifold vertices."), std::string::npos);
  const ViewPixels view = view_pixels(screenshot_of(page));
  EXPECT_GT(view.coloured, view.total / 20);
}

}  // namespace
}  // namespace envcrust::testing
