// The sheet's final manifold check and the border snap, on small face sets built here with the
// defects the face scan (issue #5, `--rho 1.8`) showed: two border vertices snapped onto one
// corner of the ragged rim, which the analyzer welds into a pinched vertex.
#include "envcrust/topology.h"

#include "sheet_mesh.h"
#include "sheet_projection.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace envcrust;
using namespace envcrust::extract;

namespace {

TaggedMesh tagged(std::vector<Point3> vertices, std::vector<std::array<Index, 3>> faces,
                  std::vector<double> dots = {}) {
  TaggedMesh t;
  t.mesh.vertices = std::move(vertices);
  t.mesh.triangles = std::move(faces);
  t.face_dot = dots.empty() ? std::vector<double>(t.mesh.triangles.size(), -1.0) : std::move(dots);
  return t;
}

// Two fans in the plane z = 0 whose apexes are distinct vertices at the same position (the
// origin): one of `upper` triangles above the x axis, one of `lower` below. Welded, the apex
// is a pinched vertex (two fans, both on the border).
TaggedMesh fans_meeting_at_one_point(int upper, int lower) {
  std::vector<Point3> v{Point3(0, 0, 0), Point3(0, 0, 0)};
  std::vector<std::array<Index, 3>> f;
  auto fan = [&](Index apex, int count, double from_deg, double to_deg) {
    const auto first = static_cast<Index>(v.size());
    for (int k = 0; k <= count; ++k) {
      const double a = (from_deg + (to_deg - from_deg) * k / count) * 3.141592653589793 / 180.0;
      v.emplace_back(std::cos(a), std::sin(a), 0.0);
    }
    for (int k = 0; k < count; ++k)
      f.push_back({apex, first + static_cast<Index>(k), first + static_cast<Index>(k) + 1});
  };
  fan(0, upper, 10, 170);
  fan(1, lower, 190, 350);
  return tagged(std::move(v), std::move(f));
}

}  // namespace

TEST(MakeManifold, issue_5_splits_two_fans_that_meet_at_one_position) {
  TaggedMesh t = fans_meeting_at_one_point(3, 3);
  ASSERT_EQ(topology::analyze_topology(t.mesh).non_manifold_vertices, 1u);  // the defect
  const auto stats = make_manifold(t);
  EXPECT_EQ(stats.vertices_welded, 1u);
  EXPECT_EQ(stats.non_manifold_vertices_found, 1u);
  EXPECT_EQ(stats.vertices_split, 1u);
  EXPECT_EQ(stats.faces_dropped, 0u);
  const auto topo = topology::analyze_topology(t.mesh);  // welds, as the report does
  EXPECT_TRUE(topo.is_manifold());
  EXPECT_EQ(topo.welded_vertices, 0u);
  EXPECT_EQ(topo.faces, 6u);
  EXPECT_EQ(topo.components.size(), 2u);  // two discs
  EXPECT_EQ(topo.euler_characteristic, 2);
  EXPECT_EQ(topo.boundary_loops.size(), 2u);
  EXPECT_EQ(t.face_dot.size(), t.mesh.triangles.size());
}

TEST(MakeManifold, issue_5_the_face_scans_pinch_of_a_three_and_a_two_face_fan) {
  // What the face scan's output had: fans of 3 and 2 faces on one welded border vertex. A fan
  // of fewer than 3 faces is dropped by the split.
  TaggedMesh t = fans_meeting_at_one_point(3, 2);
  const auto stats = make_manifold(t);
  EXPECT_EQ(stats.non_manifold_vertices_found, 1u);
  const auto topo = topology::analyze_topology(t.mesh);
  EXPECT_TRUE(topo.is_manifold());
  EXPECT_EQ(topo.faces, 3u);
  EXPECT_EQ(topo.vertices, 5u);
  EXPECT_EQ(topo.euler_characteristic, 1);
  EXPECT_EQ(topo.boundary_loops.size(), 1u);
}

TEST(MakeManifold, drops_the_faces_at_defects_it_may_not_repair) {
  TaggedMesh t = fans_meeting_at_one_point(3, 3);
  const auto stats = make_manifold(t, /*max_rounds=*/0);
  EXPECT_EQ(stats.rounds, 0);
  EXPECT_EQ(stats.faces_dropped, 3u);  // the second fan: the first keeps the vertex
  const auto topo = topology::analyze_topology(t.mesh);
  EXPECT_TRUE(topo.is_manifold());
  EXPECT_EQ(topo.faces, 3u);
  EXPECT_EQ(topo.euler_characteristic, 1);
}

TEST(MakeManifold, an_edge_that_welds_into_three_faces_keeps_the_two_most_opposite) {
  // Three triangles on the edge (0,0,0)-(1,0,0), each with its own copies of the two ends.
  std::vector<Point3> v;
  std::vector<std::array<Index, 3>> f;
  const Point3 tips[] = {Point3(0.5, 1, 0), Point3(0.5, -1, 0), Point3(0.5, 0, 1)};
  for (const Point3& tip : tips) {
    const auto first = static_cast<Index>(v.size());
    v.insert(v.end(), {Point3(0, 0, 0), Point3(1, 0, 0), tip});
    f.push_back({first, first + 1, first + 2});
  }
  TaggedMesh t = tagged(std::move(v), std::move(f), {-1.0, -0.9, 0.5});
  ASSERT_EQ(topology::analyze_topology(t.mesh).non_manifold_edges, 1u);
  const auto stats = make_manifold(t);
  EXPECT_EQ(stats.vertices_welded, 4u);
  EXPECT_EQ(stats.non_manifold_edges_found, 1u);
  EXPECT_EQ(stats.non_manifold_faces_removed, 1u);
  const auto topo = topology::analyze_topology(t.mesh);
  EXPECT_TRUE(topo.is_manifold());
  EXPECT_EQ(topo.faces, 2u);
  EXPECT_EQ(topo.euler_characteristic, 1);
  for (const Point3& p : t.mesh.vertices) EXPECT_NE(p.z(), 1.0) << "the face tagged 0.5 goes";
}

TEST(MakeManifold, leaves_a_manifold_mesh_as_it_is) {
  TaggedMesh t = fans_meeting_at_one_point(3, 3);
  t.mesh.vertices[1] = Point3(0, -0.5, 0);  // the apexes apart: two discs
  const auto before = t.mesh;
  const auto stats = make_manifold(t);
  EXPECT_EQ(stats.vertices_welded + stats.non_manifold_edges_found + stats.non_manifold_vertices_found, 0u);
  EXPECT_EQ(t.mesh.vertices, before.vertices);
  EXPECT_EQ(t.mesh.triangles, before.triangles);
}

namespace {

// The square [0, 10]^2 in the plane z = 0 as one boundary curve, its four corners only: the
// nearest point of every point beyond a corner is that corner.
envelope::SurfaceSamples square_boundary() {
  envelope::SurfaceSamples s;
  BoundaryCurve c;
  const Point3 corners[] = {Point3(0, 0, 0), Point3(10, 0, 0), Point3(10, 10, 0), Point3(0, 10, 0)};
  for (int k = 0; k < 4; ++k) {
    BoundaryVertex b;
    b.position = corners[k];
    b.tangent = corners[(k + 1) % 4] - corners[k];
    b.tangent = b.tangent / std::sqrt(b.tangent.squared_length());
    b.normal = Vector3(0, 0, 1);
    b.conormal = CGAL::cross_product(b.tangent, b.normal);
    b.is_corner = true;
    c.vertices.push_back(b);
  }
  s.boundary.push_back(c);
  return s;
}

}  // namespace

TEST(SnapBorder, issue_5_two_vertices_never_snap_onto_one_corner) {
  // Two triangles (separate pieces) each with a vertex just beyond the corner (10, 10).
  TaggedMesh t = tagged({Point3(10.3, 10.1, 0), Point3(9.8, 8.0, 0), Point3(9.0, 9.0, 0),
                         Point3(10.1, 10.3, 0), Point3(8.0, 9.8, 0), Point3(9.1, 9.1, 0)},
                        {{0, 1, 2}, {3, 4, 5}});
  snap_border(t, square_boundary(), /*max_move=*/0.5, /*retry_rounds=*/4);
  EXPECT_EQ(t.mesh.vertices[0], Point3(10, 10, 0));  // the first takes the corner
  EXPECT_NE(t.mesh.vertices[3], Point3(10, 10, 0));
  EXPECT_EQ(t.mesh.vertices[1], Point3(10, 8, 0));   // the others snap as before
  EXPECT_EQ(t.mesh.vertices[4], Point3(8, 10, 0));
  const auto topo = topology::analyze_topology(t.mesh);
  EXPECT_EQ(topo.welded_vertices, 0u);
  EXPECT_TRUE(topo.is_manifold());
  EXPECT_EQ(topo.components.size(), 2u);
}

// After a cut and its repairs only the faces it made are checked again for crossings: a face
// is new when no face before had its three corner positions, whatever the indices or order.
TEST(FacesNotIn, a_face_is_known_by_its_corner_positions) {
  TriangleMesh before;
  before.vertices = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(1, 1, 0), Point3(-0.0, 2, 0)};
  before.triangles = {{0, 1, 2}, {1, 3, 2}, {2, 3, 4}};
  TriangleMesh after;
  // The same points re-indexed (one twice), the first face turned, the second replaced by
  // one with a moved corner, the third kept (0 and -0 alike), and a new one.
  after.vertices = {Point3(1, 1, 0), Point3(0, 1, 0), Point3(1, 0, 0), Point3(0, 0, 0), Point3(0, 2, 0),
                    Point3(1, 1, 1e-12), Point3(0, 1, 0)};
  after.triangles = {{2, 6, 3}, {2, 5, 1}, {1, 0, 4}, {3, 2, 4}};
  EXPECT_EQ(faces_not_in(after, before), (std::vector<char>{0, 1, 0, 1}));
  EXPECT_EQ(faces_not_in(after, TriangleMesh{}), (std::vector<char>{1, 1, 1, 1}));
}
