#include "topology_words.h"

#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <string>

namespace envcrust::cli::html {
namespace {

std::string joined(const std::vector<std::string>& paragraphs) {
  std::string text;
  for (const auto& p : paragraphs) text += p + "\n";
  return text;
}

TEST(TopologyWords, surfaces_are_named_from_their_numbers) {
  EXPECT_EQ(surface_name(true, 0, 1), "a disc");
  EXPECT_EQ(surface_name(true, 0, 2), "an annulus (a tube open at both ends)");
  EXPECT_EQ(surface_name(true, 0, 4), "a disc with 3 holes");
  EXPECT_EQ(surface_name(true, 0, 0), "a sphere (a closed surface without handles)");
  EXPECT_EQ(surface_name(true, 1, 0), "a torus (a closed surface with one handle)");
  EXPECT_EQ(surface_name(true, 2, 1), "a surface with 2 handles and 1 boundary loop");
  EXPECT_EQ(surface_name(false, 1, 1), "a Möbius band");
  EXPECT_EQ(surface_name(false, 2, 0), "a Klein bottle");
  EXPECT_EQ(surface_name(false, 3, 2), "a one-sided surface with 3 cross-caps and 2 boundary loops");
  EXPECT_EQ(surface_name(true, std::nullopt, 1), "a set of triangles that is not a surface (not a 2-manifold)");
}

TEST(TopologyWords, moebius_band_reads_as_one_sided_with_one_loop) {
  const auto report = analysis::analyze_mesh(fixtures::moebius());
  const std::string text = joined(topology_in_words(report));
  EXPECT_NE(text.find("one piece"), std::string::npos) << text;
  EXPECT_NE(text.find("Its shape is that of a Möbius band."), std::string::npos) << text;
  EXPECT_NE(text.find("χ = V − E + F = 0"), std::string::npos) << text;
  EXPECT_NE(text.find("Here χ = 2 − 1 cross-cap − 1 loop."), std::string::npos) << text;
  EXPECT_NE(text.find("It has 1 boundary loop"), std::string::npos) << text;
  EXPECT_NE(text.find("It is not orientable"), std::string::npos) << text;
}

TEST(TopologyWords, torus_reads_as_closed_and_two_sided) {
  const auto report = analysis::analyze_mesh(fixtures::torus());
  const std::string text = joined(topology_in_words(report));
  EXPECT_NE(text.find("a torus"), std::string::npos) << text;
  EXPECT_NE(text.find("It has no boundary loop"), std::string::npos) << text;
  EXPECT_NE(text.find("It is orientable: it has two sides"), std::string::npos) << text;
  EXPECT_NE(text.find("Here χ = 2 − 2 × 1 handle − 0 loops."), std::string::npos) << text;
}

TEST(TopologyWords, three_sheets_on_one_edge_are_no_manifold) {
  TriangleMesh book;
  book.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  book.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  const auto report = analysis::analyze_mesh(book);
  const std::string text = joined(topology_in_words(report));
  EXPECT_NE(text.find("It is not a 2-manifold: 1 edge has three or more triangles"), std::string::npos) << text;
  EXPECT_NE(text.find("not a surface"), std::string::npos) << text;
}

TEST(TopologyWords, several_pieces_are_each_named) {
  TriangleMesh two = fixtures::disk_fan();
  const TriangleMesh other = fixtures::octahedron();
  const auto offset = static_cast<Index>(two.vertices.size());
  for (const auto& p : other.vertices) two.vertices.push_back(Point3(p.x() + 5, p.y(), p.z()));
  for (const auto& t : other.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const std::string text = joined(topology_in_words(analysis::analyze_mesh(two)));
  EXPECT_NE(text.find("in 2 separate pieces"), std::string::npos) << text;
  EXPECT_NE(text.find("a disc (χ 1)"), std::string::npos) << text;
  EXPECT_NE(text.find("a sphere (a closed surface without handles) (χ 2)"), std::string::npos) << text;
}

}  // namespace
}  // namespace envcrust::cli::html
