#include "html_output.h"
#include "html_report.h"

#include "fixtures/shapes.h"
#include "html/page_reader.h"

#include "envcrust/analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace envcrust::cli::html {
namespace {

using envcrust::testing::decode_block;
using envcrust::testing::script_text;

std::string page_text(const ReportPage& page) {
  std::ostringstream out;
  write_report_page(out, page);
  return out.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class HtmlReport : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!has_viewer()) GTEST_SKIP() << "built without three.js (scripts/setup.sh installs it with npm)";
  }
};

TEST_F(HtmlReport, moebius_page_holds_caption_summary_and_data_of_the_right_counts) {
  const TriangleMesh mesh = fixtures::moebius();
  const auto report = analysis::analyze_mesh(mesh);
  ReportPage page = reconstruct_page("envcrust reconstruct: moebius", mesh, &report, mesh.vertices, {}, {},
                                     {{"input_points", 160}});
  const std::string html = page_text(page);
  EXPECT_GT(html.size(), 10'000u);
  EXPECT_TRUE(contains(html, "<h1 id=\"title\">envcrust reconstruct: moebius</h1>"));
  EXPECT_TRUE(contains(html, kViewCaption));
  EXPECT_TRUE(contains(html, "Its shape is that of a Möbius band."));
  EXPECT_TRUE(contains(html, "<tr><td>input_points</td><td>160</td></tr>"));
  EXPECT_TRUE(contains(html, "three.js"));
  EXPECT_TRUE(contains(html, "export{"));  // the module itself, inlined

  const auto info = nlohmann::json::parse(script_text(html, "mesh-info"));
  EXPECT_EQ(info["vertices"], mesh.vertices.size());
  EXPECT_EQ(info["faces"], mesh.triangles.size());
  ASSERT_EQ(info["loops"].size(), 1u);
  EXPECT_EQ(info["loops"][0], report.topology.boundary_loops[0].vertices.size());

  const auto positions = decode_block<float>(html, "data-positions");
  ASSERT_EQ(positions.size(), 3 * mesh.vertices.size());
  const auto centre = info["centre"].get<std::vector<double>>();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(positions[3 * v + k] + centre[k], mesh.vertices[v][k], 1e-6);
  const auto faces = decode_block<std::uint32_t>(html, "data-faces");
  ASSERT_EQ(faces.size(), 3 * mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(faces[3 * f + k], mesh.triangles[f][k]);
  EXPECT_EQ(decode_block<float>(html, "data-loop-points").size(), 3 * info["loops"][0].get<std::size_t>());
  // The input is the mesh's own vertices: every distance is 0.
  const auto distances = decode_block<float>(html, "data-distances");
  ASSERT_EQ(distances.size(), mesh.vertices.size());
  for (const float d : distances) EXPECT_EQ(d, 0.0f);
  EXPECT_EQ(info["distance"]["label"], "distance to the nearest input point");
}

TEST_F(HtmlReport, distances_are_each_vertex_to_the_nearest_input_point) {
  const TriangleMesh mesh = fixtures::square(4);  // [0,1]^2 in the plane z = 0
  const std::vector<Point3> input = {Point3(0, 0, 0.5)};
  const auto report = analysis::analyze_mesh(mesh);
  const std::string html = page_text(reconstruct_page("square", mesh, &report, input, {}, {}, {}));
  const auto distances = decode_block<float>(html, "data-distances");
  ASSERT_EQ(distances.size(), mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto& p = mesh.vertices[v];
    EXPECT_NEAR(distances[v], std::sqrt(p.x() * p.x() + p.y() * p.y() + 0.25), 1e-6) << "vertex " << v;
  }
  const auto info = nlohmann::json::parse(script_text(html, "mesh-info"));
  EXPECT_NEAR(info["distance"]["max"].get<double>(), 1.5, 1e-9);  // sqrt(1 + 1 + 0.25)
}

TEST_F(HtmlReport, coordinates_far_from_the_origin_keep_their_precision) {
  TriangleMesh mesh = fixtures::square(4);
  for (auto& p : mesh.vertices) p = Point3(500000 + p.x() * 1e-3, 5000000 + p.y() * 1e-3, 100 + p.z());
  ReportPage page;
  page.title = "utm";
  page.mesh = &mesh;
  const std::string html = page_text(page);
  const auto info = nlohmann::json::parse(script_text(html, "mesh-info"));
  const auto centre = info["centre"].get<std::vector<double>>();
  const auto positions = decode_block<float>(html, "data-positions");
  ASSERT_EQ(positions.size(), 3 * mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(positions[3 * v + k] + centre[k], mesh.vertices[v][k], 1e-9);
}

TEST_F(HtmlReport, data_take_about_18_bytes_per_vertex_and_face) {
  const TriangleMesh small = fixtures::square(2);
  const TriangleMesh large = fixtures::square(200);  // 40,401 vertices, 80,000 faces
  auto size_of = [](const TriangleMesh& mesh) {
    std::vector<double> distances(mesh.vertices.size(), 0.5);
    ReportPage page;
    page.mesh = &mesh;
    page.vertex_distances = distances;
    return static_cast<double>(page_text(page).size());
  };
  const double elements = static_cast<double>(large.vertices.size() + large.triangles.size() -
                                              small.vertices.size() - small.triangles.size());
  const double per_element = (size_of(large) - size_of(small)) / elements;
  EXPECT_GT(per_element, 12.0);
  EXPECT_LT(per_element, 20.0);
}

TEST_F(HtmlReport, text_is_escaped_and_data_cannot_close_its_script) {
  const TriangleMesh mesh = fixtures::square(2);
  ReportPage page;
  page.title = "a <b> & \"c\"";
  page.mesh = &mesh;
  page.figures = {{"input", "</script><script>alert(1)"}};
  page.distance_label = "</script>";
  page.vertex_distances.assign(mesh.vertices.size(), 1.0);
  const std::string html = page_text(page);
  EXPECT_TRUE(contains(html, "<title>a &lt;b&gt; &amp; &quot;c&quot;</title>"));
  EXPECT_FALSE(contains(html, "</script><script>alert(1)"));
  EXPECT_TRUE(contains(html, "&lt;/script&gt;&lt;script&gt;alert(1)"));
  const auto info = nlohmann::json::parse(script_text(html, "mesh-info"));
  EXPECT_EQ(info["distance"]["label"], "</script>");
}

TEST_F(HtmlReport, page_without_a_mesh_says_so) {
  ReportPage page = failure_page("envcrust analyze: empty.off", nullptr, "empty.off: no faces");
  const std::string html = page_text(page);
  EXPECT_GT(html.size(), 10'000u);
  EXPECT_TRUE(contains(html, "<p class=\"message\">empty.off: no faces</p>"));
  EXPECT_TRUE(contains(html, "The mesh could not be analyzed: empty.off: no faces. Nothing of it could be shown."));
  EXPECT_TRUE(contains(html, "Nothing to show in 3D: the mesh has no vertices."));
  const auto info = nlohmann::json::parse(script_text(html, "mesh-info"));
  EXPECT_EQ(info["vertices"], 0);
  EXPECT_TRUE(decode_block<float>(html, "data-positions").empty());
}

TEST_F(HtmlReport, vertices_without_faces_are_shown_as_points) {
  TriangleMesh points;
  points.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::string html = page_text(failure_page("t", &points, "t.off: no faces"));
  EXPECT_TRUE(contains(html, "The view shows what could be read of it (its vertices, as points)."));
  const auto info = nlohmann::json::parse(script_text(html, "mesh-info"));
  EXPECT_EQ(info["vertices"], 3);
  EXPECT_EQ(info["faces"], 0);
  EXPECT_EQ(decode_block<float>(html, "data-positions").size(), 9u);
}

TEST_F(HtmlReport, faces_naming_missing_vertices_are_left_out_with_a_message) {
  TriangleMesh mesh = fixtures::square(1);
  mesh.triangles.push_back({0, 1, 99});
  ReportPage page;
  page.mesh = &mesh;
  const std::string html = page_text(page);
  EXPECT_TRUE(contains(html, "1 faces name a vertex the mesh does not have and are not drawn."));
  EXPECT_EQ(decode_block<std::uint32_t>(html, "data-faces").size(), 3 * (mesh.triangles.size() - 1));
}

TEST_F(HtmlReport, failed_checks_hints_and_skipped_analysis_become_messages) {
  const TriangleMesh mesh = fixtures::annulus();
  const std::string html = page_text(reconstruct_page("annulus", mesh, nullptr, mesh.vertices,
                                                      {"passes through itself (2 pairs of faces)"},
                                                      {"try --boundary-min-width 7"}, {}));
  EXPECT_TRUE(contains(html, "The result fails its checks: passes through itself (2 pairs of faces)."));
  EXPECT_TRUE(contains(html, "Hint: try --boundary-min-width 7"));
  EXPECT_TRUE(contains(html, "The analysis was skipped (--no-analysis)"));
  EXPECT_TRUE(contains(html, "an annulus (a tube open at both ends)"));
}

}  // namespace
}  // namespace envcrust::cli::html
