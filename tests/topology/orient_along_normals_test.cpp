// orient_along_normals: pieces facing against their samples' normals are turned over, whole.
#include "envcrust/topology.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

using namespace envcrust;

namespace {

// +1 when every face's normal points to +z, -1 when every one points to -z, 0 when mixed.
int facing(const TriangleMesh& mesh, std::size_t first, std::size_t last) {
  int up = 0, down = 0;
  for (std::size_t f = first; f < last; ++f) {
    const auto& t = mesh.triangles[f];
    const double z = CGAL::cross_product(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                         mesh.vertices[t[2]] - mesh.vertices[t[0]]).z();
    (z > 0 ? up : down) += 1;
  }
  return down == 0 ? 1 : up == 0 ? -1 : 0;
}

}  // namespace

TEST(OrientAlongNormals, turns_only_the_pieces_that_face_against_their_samples) {
  // Two flat unit squares side by side (x in [0,1] and [2,3]), both facing +z; the samples
  // under the second have normals -z (mostly: one in ten disagrees, as noise would).
  TriangleMesh mesh = fixtures::square(8);
  const std::size_t half = mesh.triangles.size();
  ASSERT_EQ(facing(mesh, 0, half), 1);
  const TriangleMesh copy = mesh;
  const Index offset = static_cast<Index>(mesh.vertices.size());
  for (const auto& v : copy.vertices) mesh.vertices.push_back(v + Vector3(2, 0, 0));
  for (const auto& t : copy.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  std::vector<Point3> points;
  std::vector<Vector3> normals;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      points.emplace_back(0.05 + 0.1 * i, 0.05 + 0.1 * j, 0.0);
      normals.emplace_back(0, 0, 1);
      points.emplace_back(2.05 + 0.1 * i, 0.05 + 0.1 * j, 0.0);
      normals.emplace_back(0, 0, j == 3 ? 1 : -1);
    }
  EXPECT_EQ(topology::orient_along_normals(mesh, points, normals), 1u);
  EXPECT_EQ(facing(mesh, 0, half), 1);
  EXPECT_EQ(facing(mesh, half, 2 * half), -1);
  // Already facing like the normals: nothing to turn.
  EXPECT_EQ(topology::orient_along_normals(mesh, points, normals), 0u);
  EXPECT_EQ(topology::orient_along_normals(mesh, {}, {}), 0u);
}
