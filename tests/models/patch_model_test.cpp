// Patch models: an open box of five flat patches, a tube of four quarter tubes, faces wound
// either way, patches that form no surface, and samples spread over the patches by area.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/models.h"
#include "envcrust/nurbs_surface.h"
#include "envcrust/topology.h"
#include "fixtures/nurbs_patches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace envcrust::models {
namespace {

namespace fixtures = envcrust::testing;

PatchModel model_of(const std::vector<surfaces::NurbsPatch>& patches, const JoinOptions& options = {}) {
  std::vector<std::unique_ptr<surfaces::Surface>> surfaces;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    std::string name = "patch ";  // (appended, not "patch " + ...: g++ 12's -Wrestrict misfires on that)
    name += std::to_string(i);
    surfaces.push_back(surfaces::make_nurbs_surface(patches[i], name));
  }
  return PatchModel(std::move(surfaces), "model", options);
}

double loop_length(const BoundaryCurve& curve) { return mesh::closed_length(curve.polyline()); }

TEST(PatchModel, an_open_box_of_five_squares_is_a_disc_with_its_rim) {
  const PatchModel box = model_of(fixtures::open_box_patches());
  const auto& e = box.expected_topology();
  EXPECT_EQ(e.euler_characteristic, 1);
  EXPECT_EQ(e.boundary_loops, 1);
  EXPECT_TRUE(e.is_orientable);
  EXPECT_EQ(e.boundary_knots, std::vector<std::string>{"unknot"});
  EXPECT_EQ(box.joins().joined_edges, 8u);  // the eight box edges below the rim, one quad side each
  EXPECT_EQ(box.joins().largest_gap, 0.0);
  EXPECT_NEAR(box.diagonal(), std::sqrt(3.0), 1e-12);
  const auto curves = box.boundary_curves(0.01);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_NEAR(loop_length(curves.front()), 4.0, 1e-9);  // the rim square at z = 1
  for (const auto& v : curves.front().vertices) {
    EXPECT_NEAR(v.position.z(), 1.0, 1e-12);
    EXPECT_NEAR(v.conormal.z(), 1.0, 1e-6) << v.position << " n " << v.normal << " c " << v.conormal << " t " << v.tangent;  // out of the box's sides: up
  }
  EXPECT_NEAR(mesh::total_area(box.truth()), 5.0, 1e-12);
}

TEST(PatchModel, faces_wound_either_way_join_into_one_oriented_surface) {
  auto patches = fixtures::open_box_patches();
  for (std::size_t k : {1u, 3u}) {  // two sides turned inward (u and v swapped)
    patches[k] = fixtures::transposed(patches[k]);
  }
  const PatchModel box = model_of(patches);
  EXPECT_EQ(box.expected_topology().euler_characteristic, 1);
  EXPECT_TRUE(box.expected_topology().is_orientable);
  const auto t = topology::analyze_topology(box.truth());
  EXPECT_EQ(t.misoriented_edges, 0u);
}

TEST(PatchModel, four_quarter_tubes_make_the_open_cylinder) {
  std::vector<surfaces::NurbsPatch> quarters;
  for (int q = 0; q < 4; ++q) quarters.push_back(fixtures::quarter_tube_patch(q));
  const PatchModel tube = model_of(quarters);
  const auto& e = tube.expected_topology();
  EXPECT_EQ(e.euler_characteristic, 0);
  EXPECT_EQ(e.boundary_loops, 2);
  EXPECT_EQ(e.boundary_knots, (std::vector<std::string>{"unknot", "unknot"}));
  EXPECT_EQ(e.abs_linking_number, 0);
  // The rims are the unit circles at z = 0 and 1, within the tessellation's chord error.
  for (const auto& curve : tube.boundary_curves(0.01)) {
    EXPECT_NEAR(loop_length(curve), 2 * M_PI, 2e-3);
    for (const auto& v : curve.vertices) EXPECT_NEAR(std::hypot(v.position.x(), v.position.y()), 1.0, 1e-9);
  }
}

TEST(PatchModel, a_trimmed_plate_and_a_tube_in_its_hole_join_along_the_trim_circle) {
  // The unit square trimmed by a hole of radius 0.25 at its middle, and a tube of that radius
  // hanging from the hole down to z = -0.5: a sink, an annulus (chi 0) with the square's
  // border and the tube's lower rim as its loops.
  auto plate = fixtures::square_patch();
  plate.trim_loops = {{fixtures::trim_polyline({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}})},
                      {fixtures::trim_circle(0.5, 0.5, 0.25)}};
  auto tube = fixtures::cylinder_patch();  // z in [-1, 1]
  for (auto& q : tube.control_points) q = Point3(0.5 + 0.25 * q.x(), 0.5 + 0.25 * q.y(), -0.25 * (1 - q.z()));
  const PatchModel sink = model_of({plate, tube});
  const auto& e = sink.expected_topology();
  EXPECT_EQ(e.euler_characteristic, 0);
  EXPECT_EQ(e.boundary_loops, 2);
  EXPECT_TRUE(e.is_orientable);
  EXPECT_GT(sink.joins().joined_edges, 100u);
  EXPECT_LT(sink.joins().largest_gap, 1e-4 * sink.diagonal());  // both curves exact, within the chords
  const auto curves = sink.boundary_curves(0.01);
  ASSERT_EQ(curves.size(), 2u);
  std::vector<double> lengths{loop_length(curves[0]), loop_length(curves[1])};
  std::sort(lengths.begin(), lengths.end());
  EXPECT_NEAR(lengths[0], 2 * M_PI * 0.25, 1e-3);  // the tube's rim at z = -0.5
  EXPECT_NEAR(lengths[1], 4.0, 1e-9);              // the square's border
}

TEST(PatchModel, refuses_patches_that_form_no_surface) {
  // Three flaps along the z axis: an edge of three faces.
  const auto c = [](double x, double y, double z) { return Point3(x, y, z); };
  const std::vector<surfaces::NurbsPatch> book{
      fixtures::bilinear_patch(c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)),
      fixtures::bilinear_patch(c(0, 0, 0), c(0, 1, 0), c(0, 1, 1), c(0, 0, 1)),
      fixtures::bilinear_patch(c(0, 0, 0), c(-1, -1, 0), c(-1, -1, 1), c(0, 0, 1))};
  try {
    (void)model_of(book);
    FAIL() << "three flaps on one edge were accepted";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "3 patches meet along an edge near (0, 0, 0.5) (1 such edges): the patches form no surface");
  }
  // Two squares that share one corner only.
  const std::vector<surfaces::NurbsPatch> bowtie{
      fixtures::bilinear_patch(c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0)),
      fixtures::bilinear_patch(c(1, 1, 0), c(2, 1, 0), c(2, 2, 0), c(1, 2, 0))};
  try {
    (void)model_of(bowtie);
    FAIL() << "squares touching at a corner were accepted";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "patches touch at 1 points only (a vertex whose faces form several fans): the patches form no surface");
  }
}

TEST(PatchModel, samples_spread_over_the_patches_by_area) {
  // The bottom and one side of the box, the side twice as tall: a third and two thirds.
  const auto c = [](double x, double y, double z) { return Point3(x, y, z); };
  const PatchModel model = model_of({fixtures::bilinear_patch(c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)),
                                     fixtures::bilinear_patch(c(0, 0, 0), c(1, 0, 0), c(1, 0, 2), c(0, 0, 2))});
  surfaces::SampleOptions o;
  o.count = 3001;
  o.with_normals = true;
  const PointSet points = model.sample(o);
  ASSERT_EQ(points.points.size(), 3001u);
  ASSERT_EQ(points.normals.size(), 3001u);
  std::size_t on_bottom = 0;
  for (std::size_t i = 0; i < points.points.size(); ++i) {
    const Point3& p = points.points[i];
    const bool bottom = p.z() == 0 && std::abs(points.normals[i].z()) == 1;
    const bool side = p.y() == 0 && std::abs(points.normals[i].y()) == 1;
    EXPECT_TRUE(bottom || side) << p;
    on_bottom += bottom;
  }
  EXPECT_EQ(on_bottom, 1000u);  // 3001 / 3 = 1000.33: the remainder goes to the side (2000.67)
  // Deterministic for a seed, different for another.
  EXPECT_EQ(model.sample(o).points, points.points);
  o.seed = 2;
  EXPECT_NE(model.sample(o).points, points.points);
  // Noise is a fraction of the model's diagonal (sqrt 6: the box [0, 1]^2 x [0, 2]), not of a patch's.
  o.seed = 1;
  o.noise_rel_diag = 0.01;
  const PointSet noisy = model.sample(o);
  double sum2 = 0;
  for (std::size_t i = 0; i < noisy.points.size(); ++i) sum2 += CGAL::squared_distance(noisy.points[i], points.points[i]);
  EXPECT_NEAR(std::sqrt(sum2 / (3.0 * static_cast<double>(noisy.points.size()))), 0.01 * std::sqrt(6.0), 0.002);
}

TEST(PatchModel, a_single_patch_is_the_surface_as_it_is) {
  std::vector<std::unique_ptr<surfaces::Surface>> one;
  one.push_back(surfaces::make_nurbs_surface(fixtures::cylinder_patch(), "cylinder"));
  const auto expected = one.front()->expected_topology();
  const auto truth = surfaces::tessellate(*one.front());
  const PatchModel model(std::move(one), "cylinder");
  EXPECT_EQ(model.expected_topology().euler_characteristic, expected.euler_characteristic);
  EXPECT_EQ(model.expected_topology().boundary_loops, 2);
  EXPECT_EQ(model.truth().vertices, truth.vertices);
  EXPECT_EQ(model.description(), model.patch(0).description());
}

}  // namespace
}  // namespace envcrust::models
