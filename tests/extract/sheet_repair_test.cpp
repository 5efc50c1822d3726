// The repairs as free functions (sheet_repair.h), on a sampled plane built here: a handle is
// cut and its holes closed with discs, a flap through the plane is cut out and the hole
// closed; a plane that needs no repair is left as it was, and each says what it did.
#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"
#include "envcrust/topology.h"

#include "sheet_repair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace envcrust;
using namespace envcrust::extract;

namespace {

constexpr int kCells = 60;
constexpr double kCell = 0.1;

Index grid_id(int i, int j) { return static_cast<Index>(j * (kCells + 1) + i); }

// A 60 x 60 grid of 0.1 cells over [0, 6]^2 in z = 0, without the cells where `skip(i, j)`.
template <class Skip>
TaggedMesh grid_plane(Skip skip) {
  TaggedMesh t;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) t.mesh.vertices.emplace_back(i * kCell, j * kCell, 0.0);
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      if (skip(i, j)) continue;
      t.mesh.triangles.push_back({grid_id(i, j), grid_id(i + 1, j), grid_id(i + 1, j + 1)});
      t.mesh.triangles.push_back({grid_id(i, j), grid_id(i + 1, j + 1), grid_id(i, j + 1)});
    }
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

// The plane with two 4 x 4-cell square holes, at cells [18, 22) x [28, 32) and [38, 42) x
// [28, 32), joined over the plane by a tube of 16 rings (a handle: genus 1).
TaggedMesh plane_with_a_handle() {
  TaggedMesh t =
      grid_plane([](int i, int j) { return j >= 28 && j < 32 && ((i >= 18 && i < 22) || (i >= 38 && i < 42)); });
  auto rim = [](int i0) {
    std::vector<Index> r;
    for (int k = 0; k < 4; ++k) r.push_back(grid_id(i0 + k, 28));
    for (int k = 0; k < 4; ++k) r.push_back(grid_id(i0 + 4, 28 + k));
    for (int k = 0; k < 4; ++k) r.push_back(grid_id(i0 + 4 - k, 32));
    for (int k = 0; k < 4; ++k) r.push_back(grid_id(i0, 32 - k));
    return r;
  };
  const std::vector<Index> a = rim(18), b = rim(38);
  constexpr int rings = 16;
  std::vector<std::vector<Index>> ring(rings + 1);
  ring[0] = a;
  ring[rings] = b;
  for (int r = 1; r < rings; ++r) {
    const double s = static_cast<double>(r) / rings;
    for (std::size_t k = 0; k < a.size(); ++k) {
      const Point3 p = t.mesh.vertices[a[k]], q = t.mesh.vertices[b[k]];
      ring[r].push_back(static_cast<Index>(t.mesh.vertices.size()));
      t.mesh.vertices.emplace_back(p.x() + s * (q.x() - p.x()), p.y() + s * (q.y() - p.y()),
                                   1.5 * std::sin(3.141592653589793 * s));
    }
  }
  for (int r = 0; r < rings; ++r)
    for (std::size_t k = 0; k < a.size(); ++k) {
      const std::size_t k1 = (k + 1) % a.size();
      t.mesh.triangles.push_back({ring[r][k], ring[r + 1][k], ring[r + 1][k1]});
      t.mesh.triangles.push_back({ring[r][k], ring[r + 1][k1], ring[r][k1]});
    }
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

// The plane with a square flap, 1 x 1, standing upright through it at x = 3 (z from -0.5 to
// 0.5), joined to nothing: the sheet passing through itself.
TaggedMesh plane_with_a_flap() {
  TaggedMesh t = grid_plane([](int, int) { return false; });
  const auto f = static_cast<Index>(t.mesh.vertices.size());
  for (const double z : {-0.5, 0.5})
    for (const double y : {2.5, 3.5}) t.mesh.vertices.emplace_back(3.05, y, z);
  t.mesh.triangles.push_back({f, f + 1, f + 3});
  t.mesh.triangles.push_back({f, f + 3, f + 2});
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

// The plane's samples (its grid vertices, normals up) and its rim as the one boundary curve.
envelope::SurfaceSamples plane_samples() {
  envelope::SurfaceSamples s;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      s.points.emplace_back(i * kCell, j * kCell, 0.0);
      s.normals.emplace_back(0, 0, 1);
    }
  BoundaryCurve rim;
  auto add = [&](double x, double y, Vector3 tangent, Vector3 conormal) {
    rim.vertices.push_back({.position = Point3(x, y, 0), .tangent = tangent, .normal = Vector3(0, 0, 1),
                            .conormal = conormal, .is_corner = false, .conormal_next = Vector3(0, 0, 0)});
  };
  for (int k = 0; k < kCells; ++k) add(k * kCell, 0, {1, 0, 0}, {0, -1, 0});
  for (int k = 0; k < kCells; ++k) add(6, k * kCell, {0, 1, 0}, {1, 0, 0});
  for (int k = 0; k < kCells; ++k) add(6 - k * kCell, 6, {-1, 0, 0}, {0, 1, 0});
  for (int k = 0; k < kCells; ++k) add(0, 6 - k * kCell, {0, -1, 0}, {-1, 0, 0});
  s.boundary.push_back(std::move(rim));
  return s;
}

// The site of the plane's samples at rho: a component is kept within rho / 2 of them.
struct Site {
  explicit Site(double rho)
      : surface(plane_samples()),
        index(surface.points),
        max_distance(surface.points.size(), 0.5 * rho),
        site{.surface = surface, .samples = index, .max_component_distance = max_distance,
             .boundary_points = {}, .rho = rho, .local_rho = {}} {
    for (const auto& v : surface.boundary[0].vertices) site.boundary_points.push_back(v.position);
  }
  envelope::SurfaceSamples surface;
  NearestIndex index;
  std::vector<double> max_distance;
  RepairSite site;
};

// The plane back: manifold, one piece, a disc whose one border is the rim.
void expect_a_disc(const TriangleMesh& mesh) {
  const auto t = topology::analyze_topology(mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
}

}  // namespace

TEST(RepairHandles, cuts_the_handle_and_closes_its_holes_with_discs) {
  const Site s(0.5);
  TaggedMesh sheet = plane_with_a_handle();
  ASSERT_EQ(topology::analyze_topology(sheet.mesh).euler_characteristic, -1);
  std::vector<std::string> warnings;
  const HandleRepairStats r = repair_handles(sheet, s.site, {.radius_rel_rho = 1.6}, {}, warnings);
  EXPECT_GT(r.cut.balls, 0u);
  EXPECT_GT(r.cut.faces_removed, 0u);
  EXPECT_GE(r.holes.discs, 1u);
  expect_a_disc(sheet.mesh);
  EXPECT_EQ(sheet.face_dot.size(), sheet.mesh.triangles.size());
  ASSERT_EQ(warnings.size(), 1u);
  const std::string said = "the sheet was not a disc in " + std::to_string(r.cut.balls) +
                           (r.cut.balls == 1 ? " ball" : " balls") + " of radius 1.6 rho: " +
                           std::to_string(r.cut.faces_removed) + " faces removed there; " +
                           std::to_string(r.holes.discs) + (r.holes.discs == 1 ? " hole" : " holes") +
                           " closed with a disc";
  EXPECT_EQ(warnings[0], said);
}

TEST(RepairHandles, leaves_a_plane_without_a_handle_as_it_was_and_says_nothing) {
  const Site s(0.5);
  TaggedMesh sheet = grid_plane([](int, int) { return false; });
  const TaggedMesh before = sheet;
  std::vector<std::string> warnings;
  const HandleRepairStats r = repair_handles(sheet, s.site, {.radius_rel_rho = 1.6}, {}, warnings);
  EXPECT_EQ(r.cut.balls, 0u);
  EXPECT_EQ(r.holes.discs, 0u);
  EXPECT_EQ(sheet.mesh.triangles, before.mesh.triangles);
  EXPECT_TRUE(warnings.empty());
}

TEST(RepairSelfIntersections, cuts_a_flap_through_the_plane_and_closes_the_hole) {
  const Site s(0.2);
  TaggedMesh sheet = plane_with_a_flap();
  std::vector<std::string> warnings;
  const SelfIntersectionRepairStats r = repair_self_intersections(sheet, s.site, {}, {}, warnings);
  EXPECT_GT(r.found, 0u);
  EXPECT_EQ(r.left, 0u);
  EXPECT_EQ(mesh::self_intersections(sheet.mesh, 0).face_pairs, 0u);
  expect_a_disc(sheet.mesh);
  // Nothing is left above or below the plane: the flap went as a crumb.
  for (const auto& p : sheet.mesh.vertices) EXPECT_NEAR(p.z(), 0.0, 1e-9);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("the sheet passed through itself at " + std::to_string(r.found) + " face pairs: relaxed there", 0),
            0u)
      << warnings[0];
}

TEST(RepairSelfIntersections, finds_nothing_on_a_plane_and_says_nothing) {
  const Site s(0.2);
  TaggedMesh sheet = grid_plane([](int, int) { return false; });
  std::vector<std::string> warnings;
  const SelfIntersectionRepairStats r = repair_self_intersections(sheet, s.site, {}, {}, warnings);
  EXPECT_EQ(r.found, 0u);
  EXPECT_EQ(r.rounds, 0);
  EXPECT_EQ(r.left, 0u);
  EXPECT_TRUE(warnings.empty());
}
