// smooth_self_intersections on small meshes built here: a fold that relaxing opens is opened;
// a relaxation that ends by pushing the sheet through another one is taken back.
#include "envcrust/mesh.h"

#include "sheet_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace envcrust;
using namespace envcrust::extract;

namespace {

// A tent over the unit hexagon (apex (0, 0, 1), the six corners in z = 0), pierced through
// the face over its first sector by a small upright triangle; with `posts`, two small upright
// triangles stand under the apex (x = +-0.03, z in [-0.1, 0.1]), far below the tent.
TriangleMesh pierced_tent(bool posts) {
  TriangleMesh m;
  m.vertices.emplace_back(0.0, 0.0, 1.0);
  for (int i = 0; i < 6; ++i) m.vertices.emplace_back(std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), 0.0);
  for (Index i = 0; i < 6; ++i) m.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  // The face over the first sector is z = 1 - x - y / sqrt(3): 0.333 at (0.5, 0.289).
  const auto b = static_cast<Index>(m.vertices.size());
  m.vertices.emplace_back(0.45, 0.289, 0.133);
  m.vertices.emplace_back(0.55, 0.289, 0.133);
  m.vertices.emplace_back(0.5, 0.289, 0.533);
  m.triangles.push_back({b, b + 1, b + 2});
  if (posts) {
    for (const double x : {0.03, -0.03}) {
      const auto p = static_cast<Index>(m.vertices.size());
      m.vertices.emplace_back(x, -0.05, -0.1);
      m.vertices.emplace_back(x, 0.05, -0.1);
      m.vertices.emplace_back(x, 0.0, 0.1);
      m.triangles.push_back({p, p + 1, p + 2});
    }
  }
  return m;
}

TEST(SmoothSelfIntersections, RelaxingOpensAFold) {
  TriangleMesh m = pierced_tent(false);
  const auto found = mesh::self_intersections(m, 0);
  ASSERT_EQ(found.face_pairs, 1u);
  // Three umbrella steps flatten the tent into z = 0 (its rim shrinks along itself) and
  // shrink the upright triangle about its centre, above it.
  EXPECT_EQ(smooth_self_intersections(m, found, 3).face_pairs, 0u);
  EXPECT_EQ(mesh::self_intersections(m, 0).face_pairs, 0u);
  EXPECT_NEAR(m.vertices[0].z(), 0.0, 1e-12);
}

// The same relaxation flattens the tent onto the posts under its apex (4 pairs for the 1 it
// found). Allowed one round, it is taken back, and the mesh is left as it was; allowed three,
// the next rounds relax the posts too, and none is left.
TEST(SmoothSelfIntersections, ARelaxationThatEndsWithMoreCrossingsIsTakenBack) {
  TriangleMesh m = pierced_tent(true);
  const TriangleMesh before = m;
  const auto found = mesh::self_intersections(m, 0);
  ASSERT_EQ(found.face_pairs, 1u);
  TriangleMesh without_posts = pierced_tent(false);
  smooth_self_intersections(without_posts, mesh::self_intersections(without_posts, 0), 1);
  TriangleMesh relaxed_with_posts = m;  // where the relaxation would have put the tent
  for (std::size_t v = 0; v < without_posts.vertices.size(); ++v) relaxed_with_posts.vertices[v] = without_posts.vertices[v];
  ASSERT_EQ(mesh::self_intersections(relaxed_with_posts, 0).face_pairs, 4u);
  const auto left = smooth_self_intersections(m, found, 1);
  EXPECT_EQ(left.face_pairs, 1u);
  EXPECT_EQ(left.face_list, found.face_list);
  EXPECT_EQ(m.vertices, before.vertices);
  EXPECT_EQ(smooth_self_intersections(m, found, 3).face_pairs, 0u);
  EXPECT_EQ(mesh::self_intersections(m, 0).face_pairs, 0u);
}

}  // namespace
