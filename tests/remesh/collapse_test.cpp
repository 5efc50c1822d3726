// collapse_edges: pieces collapsed in parallel come back as one mesh with the input's
// topology, shared vertices once, border and fixed vertices where they were.
#include "collapse.h"

#include "envcrust/errors.h"
#include "envcrust/topology.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace envcrust;

namespace {

constexpr Index kNone = std::numeric_limits<Index>::max();

// Same as the input as topology reads it, vertices as indexed (no welding by position): a
// shared vertex copied into two pieces and not merged back would open a slit (more loops).
void expect_same_topology(const TriangleMesh& a, const TriangleMesh& b) {
  topology::TopologyOptions as_indexed;
  as_indexed.weld_identical_vertices = false;
  const auto ta = topology::analyze_topology(a, as_indexed), tb = topology::analyze_topology(b, as_indexed);
  EXPECT_TRUE(tb.is_manifold());
  EXPECT_EQ(tb.euler_characteristic, ta.euler_characteristic);
  EXPECT_EQ(tb.boundary_loops.size(), ta.boundary_loops.size());
  EXPECT_EQ(tb.components.size(), ta.components.size());
  EXPECT_EQ(tb.is_orientable, ta.is_orientable);
  EXPECT_EQ(topology::analyze_topology(b).welded_vertices, 0u);  // no two vertices at one point
}

}  // namespace

TEST(CollapseShortEdges, pieces_come_back_as_one_mesh_with_the_inputs_topology) {
  const TriangleMesh grid = fixtures::square(120);  // 28,800 faces, edges 1/120
  std::vector<char> fixed(grid.vertices.size(), 0);
  fixed[grid.vertices.size() / 2 + 7] = 1;  // an inner vertex that must stay
  remesh::CollapseOptions options;
  options.max_length = 0.03;
  options.max_border_edge = 0.05;
  for (const std::size_t per_piece : {std::size_t{1000000}, std::size_t{3000}, std::size_t{1000}, std::size_t{1}}) {
    options.faces_per_piece = per_piece;  // 1, 9, 28 and 64 pieces (at most)
    const auto out = remesh::collapse_edges(grid, fixed, options);
    SCOPED_TRACE(per_piece);
    // The bands along the pieces' shared vertices stay fine (the remeshing takes them on).
    EXPECT_LT((per_piece > grid.triangles.size() ? 4 : 1) * out.mesh.triangles.size(), grid.triangles.size());
    expect_same_topology(grid, out.mesh);
    ASSERT_EQ(out.input_vertex.size(), out.mesh.vertices.size());
    // The fixed vertex is still there, where it was, and says so.
    const Index kept = static_cast<Index>(grid.vertices.size() / 2 + 7);
    EXPECT_EQ(std::count(out.input_vertex.begin(), out.input_vertex.end(), kept), 1);
    for (std::size_t v = 0; v < out.mesh.vertices.size(); ++v)
      if (out.input_vertex[v] != kNone) {
        EXPECT_EQ(out.mesh.vertices[v], grid.vertices[out.input_vertex[v]]);
      }
    // Border vertices stay on the square's border, corners included.
    const auto t = topology::analyze_topology(out.mesh);
    ASSERT_EQ(t.boundary_loops.size(), 1u);
    for (const Index v : t.boundary_loops[0].vertices) {
      const Point3& p = t.points[v];
      EXPECT_LT(std::min({std::abs(p.x()), std::abs(1 - p.x()), std::abs(p.y()), std::abs(1 - p.y())}), 1e-12) << p;
    }
  }
}

TEST(CollapseShortEdges, result_does_not_depend_on_the_thread_schedule) {
  remesh::CollapseOptions options;
  options.max_length = 0.1;
  options.max_border_edge = 0.15;
  options.faces_per_piece = 1500;
  const TriangleMesh torus = fixtures::torus(200, 80);
  const std::vector<char> none(torus.vertices.size(), 0);
  const auto first = remesh::collapse_edges(torus, none, options);
  expect_same_topology(torus, first.mesh);
  for (int run = 0; run < 3; ++run) {
    const auto again = remesh::collapse_edges(torus, none, options);
    EXPECT_EQ(again.mesh.vertices, first.mesh.vertices);
    EXPECT_EQ(again.mesh.triangles, first.mesh.triangles);
  }
}

TEST(CollapseShortEdges, refuses_faces_that_are_no_halfedge_mesh) {
  TriangleMesh m = fixtures::square(2);
  m.triangles.push_back(m.triangles[0]);  // an edge used twice the same way
  const std::vector<char> fixed(m.vertices.size(), 0);
  remesh::CollapseOptions options;
  options.max_length = 0.1;
  try {
    (void)remesh::collapse_edges(m, fixed, options);
    FAIL() << "no exception";
  } catch (const NumericalFailure& e) {
    EXPECT_STREQ(e.what(), "remeshing: the faces cannot be oriented into a halfedge mesh");
  }
}
