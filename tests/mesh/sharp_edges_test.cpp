// sharp_edges: the edges along which a mesh bends by more than a threshold, whatever the
// winding of the faces.
#include "envcrust/mesh.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

using namespace envcrust;

TEST(SharpEdges, a_sheet_folded_by_90_degrees_has_its_fold_and_nothing_else) {
  const auto sharp = mesh::sharp_edges(fixtures::folded_sheet(90.0, 20), 80.0);
  EXPECT_EQ(sharp.count, 20u);
  EXPECT_NEAR(sharp.total_length, 1.0, 1e-12);
  EXPECT_NEAR(sharp.max_bend_deg, 90.0, 1e-9);
  ASSERT_TRUE(sharp.sharpest.has_value());
  EXPECT_NEAR(sharp.sharpest->x(), 0.0, 1e-12);  // on the fold line x = z = 0
  EXPECT_NEAR(sharp.sharpest->z(), 0.0, 1e-12);
  // Bent less than the threshold: none, and the bend is still measured.
  const auto mild = mesh::sharp_edges(fixtures::folded_sheet(75.0, 20), 80.0);
  EXPECT_EQ(mild.count, 0u);
  EXPECT_FALSE(mild.sharpest.has_value());
  EXPECT_NEAR(mild.max_bend_deg, 75.0, 1e-9);
}

TEST(SharpEdges, a_flat_sheet_has_none_and_one_folded_back_reads_near_180) {
  const auto flat = mesh::sharp_edges(fixtures::folded_sheet(0.0, 10), 1.0);
  EXPECT_EQ(flat.count, 0u);
  EXPECT_NEAR(flat.max_bend_deg, 0.0, 1e-6);
  const auto back = mesh::sharp_edges(fixtures::folded_sheet(170.0, 10), 100.0);
  EXPECT_EQ(back.count, 10u);
  EXPECT_NEAR(back.max_bend_deg, 170.0, 1e-9);
}

TEST(SharpEdges, the_winding_of_the_faces_does_not_change_the_bend) {
  TriangleMesh sheet = fixtures::folded_sheet(90.0, 12);
  for (std::size_t f = 0; f < sheet.triangles.size(); f += 3) std::swap(sheet.triangles[f][1], sheet.triangles[f][2]);
  // Faces wound against their neighbours would read as folded flat (180) if compared as wound.
  const auto sharp = mesh::sharp_edges(sheet, 1.0);
  EXPECT_EQ(sharp.count, 12u);
  EXPECT_NEAR(sharp.max_bend_deg, 90.0, 1e-9);
}

TEST(SharpEdges, border_edges_and_degenerate_faces_are_left_out) {
  constexpr int n = 4;
  TriangleMesh sheet = fixtures::folded_sheet(90.0, n);
  // A zero-area face on the fold's first edge (fold vertices j and j + 1 are j (2n + 1) + n):
  // counted, it would give that edge three faces and take it out.
  sheet.vertices.emplace_back(0, 0.5 / n, 0);
  sheet.triangles.push_back({static_cast<Index>(n), static_cast<Index>(2 * n + 1 + n),
                             static_cast<Index>(sheet.vertices.size() - 1)});
  const auto sharp = mesh::sharp_edges(sheet, 80.0);
  EXPECT_EQ(sharp.count, static_cast<std::size_t>(n));  // the border's edges have one face each
}

TEST(SharpEdges, each_fold_segment_carries_the_bisector_of_the_wedge_between_its_faces) {
  // The sheet runs along -x at z = 0 and, past the fold x = z = 0, up along +z: the faces meet
  // at 90 degrees on the side of (-1, 0, 1), whichever way the faces are wound.
  for (const bool flipped : {false, true}) {
    auto sheet = fixtures::folded_sheet(90.0, 20);
    if (flipped)
      for (auto& t : sheet.triangles) std::swap(t[1], t[2]);
    const auto sharp = mesh::sharp_edges(sheet, 80.0);
    ASSERT_EQ(sharp.segments.size(), 20u);
    for (const auto& crease : sharp.segments) {
      EXPECT_NEAR(crease.a.x(), 0.0, 1e-12);
      EXPECT_NEAR(crease.b.z(), 0.0, 1e-12);
      EXPECT_NEAR(crease.wedge.x(), -std::sqrt(0.5), 1e-9);
      EXPECT_NEAR(crease.wedge.y(), 0.0, 1e-9);
      EXPECT_NEAR(crease.wedge.z(), std::sqrt(0.5), 1e-9);
    }
  }
}
