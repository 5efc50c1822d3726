// Tests of boundary_from_points: curves through boundary points the user gives (sparse,
// unevenly spaced, off the samples, with or without conormals), and its input checks.
#include "support.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/mesh.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace envcrust {
namespace {

struct Cloud {
  PointSet samples;
  std::vector<Vector3> normal_lines;
  std::vector<BoundaryCurve> truth;  ///< exact boundary, finely resampled
  double spacing = 0;
};

Cloud sample_cloud(const std::string& name, std::size_t count) {
  Cloud c;
  const auto surface = surfaces::make_builtin(name);
  surfaces::SampleOptions o;
  o.count = count;
  o.seed = 5;
  c.samples = surfaces::sample_surface(*surface, o);
  c.normal_lines = normals::estimate_normal_lines(c.samples.points);
  c.spacing = normals::average_spacing(c.samples.points, 6);
  c.truth = surfaces::boundary_curves(*surface, c.spacing / 8);
  return c;
}

// Worst distance (in spacings) from a true loop to the nearest given-boundary curve, and the
// smallest c . c_true over the curves' vertices.
struct Agreement {
  double worst_hausdorff = 0;
  double min_conormal_dot = 1;
};
Agreement compare(const Cloud& cloud, const boundary::BoundaryDetection& d) {
  Agreement a;
  for (const BoundaryCurve& t : cloud.truth) {
    double best = std::numeric_limits<double>::infinity();
    for (const BoundaryCurve& c : d.curves)
      best = std::min(best, distance::closed_polyline_hausdorff(t.polyline(), c.polyline()));
    a.worst_hausdorff = std::max(a.worst_hausdorff, best / cloud.spacing);
  }
  const test::TruthIndex truth(cloud.truth);
  for (const BoundaryCurve& c : d.curves)
    for (const BoundaryVertex& v : c.vertices)
      a.min_conormal_dot = std::min(a.min_conormal_dot, CGAL::scalar_product(v.conormal, truth.nearest(v.position).first->conormal));
  return a;
}

// Every k-th vertex of the exact loops, as a user would pick them off a picture.
PointSet every_kth(const std::vector<BoundaryCurve>& curves, std::size_t k) {
  PointSet given;
  for (const BoundaryCurve& c : curves)
    for (std::size_t i = 0; i < c.vertices.size(); i += k) given.points.push_back(c.vertices[i].position);
  return given;
}

TEST(GivenBoundary, SparseExactPointsGiveOneCurvePerLoop) {
  for (const std::string name : {"cylinder", "trefoil-ribbon", "moebius", "saddle"}) {
    const Cloud cloud = sample_cloud(name, 10000);
    // Exact loops resampled at s/8: every 24th vertex is 3 spacings apart, off the samples.
    const auto d = boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, every_kth(cloud.truth, 24));
    EXPECT_EQ(d.curves.size(), cloud.truth.size()) << name;
    EXPECT_TRUE(d.warnings.empty()) << name << ": " << (d.warnings.empty() ? "" : d.warnings.front());
    const Agreement a = compare(cloud, d);
    // Each mark lies within a spacing or so of the true boundary; the smoothing moves little.
    EXPECT_LT(a.worst_hausdorff, 2.5) << name;
    EXPECT_GT(a.min_conormal_dot, 0.7) << name;
  }
}

TEST(GivenBoundary, UnevenlySpacedPointsInClustersStayOneLoop) {
  // Triples of close points with gaps of 7 spacings between them (a decimated scan's border
  // looks like this): longer than the detector's link distance of 5 spacings.
  const Cloud cloud = sample_cloud("cylinder", 10000);
  PointSet given;
  for (const BoundaryCurve& c : cloud.truth)
    for (std::size_t i = 0; i + 8 < c.vertices.size(); i += 64)
      for (std::size_t j = 0; j < 3; ++j) given.points.push_back(c.vertices[i + 4 * j].position);
  const auto d = boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, given);
  ASSERT_EQ(d.curves.size(), 2u);
  EXPECT_LT(compare(cloud, d).worst_hausdorff, 3.0);
}

TEST(GivenBoundary, SharpCornersStayOneLoop) {
  // The square's four corners turn by 90 degrees; with a sparse pick each corner point's
  // "other side" neighbour search must not jump to the far side.
  const Cloud cloud = sample_cloud("square", 10000);
  const auto d = boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, every_kth(cloud.truth, 16));
  ASSERT_EQ(d.curves.size(), 1u);
  const Agreement a = compare(cloud, d);
  EXPECT_LT(a.worst_hausdorff, 3.0);
}

TEST(GivenBoundary, GivenConormalsAreUsed) {
  const Cloud cloud = sample_cloud("hemisphere", 10000);
  PointSet given;
  for (const BoundaryCurve& c : cloud.truth)
    for (std::size_t i = 0; i < c.vertices.size(); i += 16) {
      given.points.push_back(c.vertices[i].position);
      given.normals.push_back(c.vertices[i].conormal);
    }
  const auto d = boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, given);
  ASSERT_EQ(d.curves.size(), 1u);
  EXPECT_GT(compare(cloud, d).min_conormal_dot, 0.9);
  // The marked samples carry the given conormals (made tangent to their normal line).
  const test::TruthIndex truth(cloud.truth);
  std::size_t marked = 0;
  for (std::size_t i = 0; i < cloud.samples.size(); ++i) {
    if (!d.is_boundary_point[i]) continue;
    ++marked;
    EXPECT_GT(CGAL::scalar_product(d.conormals[i], truth.nearest(cloud.samples.points[i]).first->conormal), 0.9);
  }
  EXPECT_GT(marked, 20u);
}

TEST(GivenBoundary, ClosedSurfaceWithGivenLoopGetsIt) {
  // A loop given on a closed sphere (say, where the user wants a cut) is taken as given.
  const Cloud cloud = sample_cloud("sphere", 10000);
  PointSet given;
  for (int i = 0; i < 60; ++i) {
    const double t = 2 * 3.14159265358979 * i / 60;
    given.points.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  const auto d = boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, given);
  ASSERT_EQ(d.curves.size(), 1u);
  for (const BoundaryVertex& v : d.curves[0].vertices) EXPECT_LT(std::abs(v.position.z()), 3 * cloud.spacing);
}

TEST(GivenBoundary, BunnyScanHolesFromItsOwnMeshBorder) {
  // The zippered bunny's five holes, given as the border vertices of its mesh (223 points,
  // edges 1-3.8 mm, clustered in places): sharp corners where two base holes come within
  // 5.2 mm. Each hole must come out as its own loop.
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "stanford_bunny_zipper";
  if (!std::filesystem::exists(folder / "bun_zipper.ply")) GTEST_SKIP() << "no " << folder;
  const TriangleMesh mesh = mesh::triangulate_polygons(io::read_polygon_mesh(folder / "bun_zipper.ply"));
  const auto topology = topology::analyze_topology(mesh);
  const auto& loops = topology.boundary_loops;
  ASSERT_EQ(loops.size(), 5u);
  PointSet given;
  for (const auto& loop : loops)
    for (const Index v : loop.vertices) given.points.push_back(topology.points[v]);
  const PointSet cloud = io::read_points(folder / "points.xyz");
  const auto d = boundary::boundary_from_points(cloud.points, normals::estimate_normal_lines(cloud.points), given);
  ASSERT_EQ(d.curves.size(), 5u);
  EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
  // Each true loop is matched by a curve within a few spacings.
  for (const auto& loop : loops) {
    double best = std::numeric_limits<double>::infinity();
    for (const BoundaryCurve& c : d.curves)
      best = std::min(best, distance::closed_polyline_hausdorff(loop.polyline(topology.points), c.polyline()));
    EXPECT_LT(best / d.spacing, 4.0);
  }
}

TEST(GivenBoundary, RefusesBadInput) {
  const Cloud cloud = sample_cloud("cylinder", 2000);
  EXPECT_THROW(
      {
        try {
          boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, PointSet{});
        } catch (const InvalidInput& e) {
          EXPECT_STREQ(e.what(), "no boundary points given");
          throw;
        }
      },
      InvalidInput);
  PointSet far = every_kth(cloud.truth, 8);
  far.points[3] = Point3(0, 0, 5);  // the cylinder spans z in [-1, 1]
  try {
    boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, far);
    FAIL() << "a point far from the samples was accepted";
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("boundary point 3 at (0, 0, 5) is ", 0), 0u) << message;
    EXPECT_NE(message.find(" spacings from the nearest sample (at most 5)"), std::string::npos) << message;
  }
  PointSet wrong_normals = every_kth(cloud.truth, 8);
  wrong_normals.normals.assign(2, Vector3(1, 0, 0));
  EXPECT_THROW(boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, wrong_normals), InvalidInput);
  // The samples given as their own boundary.
  try {
    boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, cloud.samples);
    FAIL() << "the samples were accepted as their own boundary";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "the 2000 boundary points given fall on 2000 of the 2000 samples, more than half: a "
                           "boundary is the rim of the surface, not the surface");
  }
  PointSet nan = every_kth(cloud.truth, 8);
  nan.points[0] = Point3(std::nan(""), 0, 0);
  EXPECT_THROW(boundary::boundary_from_points(cloud.samples.points, cloud.normal_lines, nan), InvalidInput);
}

}  // namespace
}  // namespace envcrust
