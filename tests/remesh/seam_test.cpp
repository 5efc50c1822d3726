// Cutting along the orientation seam opens a Moebius band into an oriented disc; welding by
// the copies' keys closes it again into the input.
#include "envcrust/errors.h"
#include "envcrust/topology.h"
#include "fixtures/shapes.h"
#include "seam.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace envcrust;

namespace {

topology::MeshTopology topology_as_indexed(const TriangleMesh& m) {
  topology::TopologyOptions o;
  o.weld_identical_vertices = false;  // the cut's copies share positions on purpose
  return topology::analyze_topology(m, o);
}

// Same three vertices in the same or in the reversed cyclic order.
bool same_face_up_to_orientation(const std::array<Index, 3>& a, const std::array<Index, 3>& b, bool& reversed) {
  for (int r = 0; r < 3; ++r) {
    if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) {
      reversed = false;
      return true;
    }
    if (a[0] == b[r] && a[1] == b[(r + 2) % 3] && a[2] == b[(r + 1) % 3]) {
      reversed = true;
      return true;
    }
  }
  return false;
}

}  // namespace

TEST(Seam, cutting_a_moebius_band_gives_an_oriented_disc) {
  const TriangleMesh band = fixtures::moebius(40, 4);
  const auto before = topology_as_indexed(band);
  ASSERT_FALSE(before.is_orientable);
  ASSERT_EQ(before.euler_characteristic, 0);

  const auto cut = remesh::cut_along_seam(band);
  const auto t = topology_as_indexed(cut.mesh);
  EXPECT_TRUE(t.is_orientable);
  EXPECT_EQ(t.misoriented_edges, 0u);  // the faces come out consistently oriented
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.euler_characteristic, 1);  // a disc
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.components.size(), 1u);

  // The seam crosses the band (4 rows of quads: at least 4 edges), a path from border to
  // border: k edges, k + 1 vertices copied once each, each edge now a border edge twice.
  const std::size_t k = cut.seam_edges.size();
  EXPECT_GE(k, 4u);
  EXPECT_LE(k, 12u);
  EXPECT_EQ(cut.mesh.vertices.size(), band.vertices.size() + k + 1);
  EXPECT_EQ(t.boundary_edges, before.boundary_edges + 2 * k);
  EXPECT_EQ(cut.mesh.triangles.size(), band.triangles.size());
  EXPECT_GT(cut.reversed_faces, 0u);
  std::size_t seam_vertices = 0;
  for (std::size_t v = 0; v < cut.mesh.vertices.size(); ++v) {
    EXPECT_EQ(cut.mesh.vertices[v], band.vertices[cut.weld_key[v]]);
    if (cut.on_seam[v]) ++seam_vertices;
  }
  EXPECT_EQ(seam_vertices, 2 * (k + 1));
}

TEST(Seam, welding_the_cut_gives_back_the_input) {
  const TriangleMesh band = fixtures::moebius(40, 4);
  const auto cut = remesh::cut_along_seam(band);
  const TriangleMesh welded = remesh::weld(cut.mesh, cut.weld_key);
  EXPECT_EQ(welded.vertices, band.vertices);
  ASSERT_EQ(welded.triangles.size(), band.triangles.size());
  std::size_t reversed_faces = 0;
  for (std::size_t f = 0; f < band.triangles.size(); ++f) {
    bool reversed = false;
    EXPECT_TRUE(same_face_up_to_orientation(welded.triangles[f], band.triangles[f], reversed)) << "face " << f;
    if (reversed) ++reversed_faces;
  }
  EXPECT_EQ(reversed_faces, cut.reversed_faces);
  const auto t = topology_as_indexed(welded);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_FALSE(t.is_orientable);
}

TEST(Seam, a_search_started_at_the_seam_cuts_half_way_round_from_it) {
  const TriangleMesh band = fixtures::moebius(40, 4);
  const auto first = remesh::cut_along_seam(band);
  std::set<Index> first_seam;
  for (const auto& [a, b] : first.seam_edges) first_seam.insert({a, b});
  std::uint32_t at_seam = 0;
  while (!first_seam.count(band.triangles[at_seam][0])) ++at_seam;
  const auto second = remesh::cut_along_seam(band, {at_seam});
  ASSERT_FALSE(second.seam_edges.empty());
  // The band is 40 quads round: the new seam is some 20 quads away, sharing no vertex.
  for (const auto& [a, b] : second.seam_edges) {
    EXPECT_FALSE(first_seam.count(a)) << a;
    EXPECT_FALSE(first_seam.count(b)) << b;
  }
  const auto t = topology_as_indexed(second.mesh);
  EXPECT_TRUE(t.is_orientable);
  EXPECT_EQ(t.euler_characteristic, 1);
}

TEST(Seam, an_orientable_mesh_has_no_seam_and_only_gets_its_flipped_faces_reversed) {
  TriangleMesh m = fixtures::open_cylinder(24, 6);
  for (std::size_t f = 5; f < m.triangles.size(); f += 7) std::swap(m.triangles[f][0], m.triangles[f][1]);
  const auto cut = remesh::cut_along_seam(m);
  EXPECT_TRUE(cut.seam_edges.empty());
  EXPECT_EQ(cut.mesh.vertices, m.vertices);
  EXPECT_EQ(cut.reversed_faces, (m.triangles.size() - 5 + 6) / 7);  // face 0 keeps its orientation
  EXPECT_TRUE(std::none_of(cut.on_seam.begin(), cut.on_seam.end(), [](bool b) { return b; }));
  const auto t = topology_as_indexed(cut.mesh);
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_loops.size(), 2u);
}

TEST(Seam, long_seam_edges_are_split_alike_on_both_sides) {
  const TriangleMesh band = fixtures::moebius(40, 4);
  auto cut = remesh::cut_along_seam(band);
  const std::size_t k = cut.seam_edges.size();
  double shortest = 1e300;
  for (const auto& [a, b] : cut.seam_edges)
    shortest = std::min(shortest, std::sqrt(CGAL::squared_distance(band.vertices[a], band.vertices[b])));
  const double max_length = 0.45 * shortest;  // every seam edge in three or more pieces
  remesh::split_long_seam_edges(cut, max_length);

  EXPECT_GE(cut.seam_edges.size(), 3 * k);
  std::set<Index> keys;
  for (const auto& [a, b] : cut.seam_edges) {
    EXPECT_LT(a, b);
    keys.insert(a);
    keys.insert(b);
  }
  EXPECT_EQ(keys.size(), cut.seam_edges.size() + 1);  // still a path
  const auto t = topology_as_indexed(cut.mesh);
  EXPECT_TRUE(t.is_orientable);
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(t.degenerate_faces, 0u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_edges, topology_as_indexed(band).boundary_edges + 2 * cut.seam_edges.size());
  // Every seam piece, on both sides, is short enough.
  const std::set<std::array<Index, 2>> seam(cut.seam_edges.begin(), cut.seam_edges.end());
  std::size_t sides = 0;
  for (const auto& tri : cut.mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const Index u = tri[i], v = tri[(i + 1) % 3];
      const Index a = std::min(cut.weld_key[u], cut.weld_key[v]), b = std::max(cut.weld_key[u], cut.weld_key[v]);
      if (!cut.on_seam[u] || !cut.on_seam[v] || !seam.count({a, b})) continue;
      ++sides;
      EXPECT_LE(std::sqrt(CGAL::squared_distance(cut.mesh.vertices[u], cut.mesh.vertices[v])), max_length * (1 + 1e-12));
    }
  }
  EXPECT_EQ(sides, 2 * cut.seam_edges.size());

  // Both sides hold the same points: welding by key succeeds and closes the band again.
  const TriangleMesh welded = remesh::weld(cut.mesh, cut.weld_key);
  const auto w = topology::analyze_topology(welded);  // welds identical positions too: none left
  EXPECT_EQ(w.welded_vertices, 0u);
  EXPECT_EQ(w.euler_characteristic, 0);
  EXPECT_EQ(w.boundary_loops.size(), 1u);
  EXPECT_FALSE(w.is_orientable);
  EXPECT_TRUE(w.is_manifold());
  EXPECT_EQ(welded.vertices.size(), band.vertices.size() + (cut.seam_edges.size() - k));
}

TEST(Seam, weld_refuses_copies_that_moved_apart) {
  TriangleMesh m = fixtures::square(1);
  const std::vector<Index> key = {0, 1, 2, 0};  // vertex 3 claims to be a copy of vertex 0
  EXPECT_THROW((void)remesh::weld(m, key), NumericalFailure);
}
