// Point files of open built-in surfaces (normals estimated, boundary detected) against the
// accuracy the samples allow: the mesh within 0.5% of the diagonal of the true surface, and
// the true surface within max(0.5%, 1.1 x the largest distance from the true boundary to the
// nearest input point) of the mesh: near an open boundary the samples stop short of it, and
// no reconstruction can know how far.
#include "cli_fixture.h"

#include "envcrust/io.h"
#include "envcrust/surfaces.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <iostream>
#include <sstream>
#include <string>
#include <tuple>

namespace envcrust::testing {
namespace {

// Largest distance from the true boundary curves to the nearest input point.
double boundary_gap(const surfaces::Surface& surface, const std::vector<Point3>& points) {
  using Tree = CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_3<Kernel>>::Tree;
  using Search = CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_3<Kernel>>;
  const Tree tree(points.begin(), points.end());
  double worst = 0.0;
  for (const auto& curve : surfaces::boundary_curves(surface, surfaces::bbox_diagonal(surface) * 1e-4))
    for (const auto& v : curve.vertices) {
      const Search search(tree, v.position, 1);
      worst = std::max(worst, std::sqrt(search.begin()->second));
    }
  return worst;
}

// (surface, seed, noise as a fraction of the diagonal)
using Case = std::tuple<std::string, int, double>;

class PointFileAccuracy : public CliTest, public ::testing::WithParamInterface<Case> {};

// Before the detected curves were fitted to the outermost samples (they lay on the centre
// line of the flagged band, about 0.8 spacings inside the samples' rim), the first two read
// truth->mesh 2.66% against a bar of 2.27% (cylinder) and 1.13% against 1.11% (trefoil
// ribbon); now 2.05% and 0.86%. The noisy Moebius strip (0.25% of the diagonal) reads 1.83%
// against 1.96%, mesh->truth 0.41%. The unknot ribbon (seed 1) once got a notch 1.07 rho
// deep: its detected rim folded back on itself at one vertex after the fit, the fold flipped
// the conormal there and the rim's envelope turned inwards (mesh->truth 0.69%); now 0.05%.
// The noisy unknot ribbon (seed 3) kept a spike 1.7 rho beyond its rim, just out of the
// trim's reach of 2 rho (mesh->truth 1.89%); now 0.42%.
TEST_P(PointFileAccuracy, issue_5_is_as_close_as_the_samples_allow) {
  const auto& [name, seed, noise] = GetParam();
  std::ostringstream sample;
  sample << "sample " << name << " -n 10000 --seed " << seed << " --noise " << noise << " -q -o " << path("p.xyz");
  ASSERT_EQ(run_envcrust(sample.str()).exit_code, 0);
  const auto j = run_envcrust_json("reconstruct " + path("p.xyz") + " -r builtin:" + name + " -o " + path("m.ply") +
                                   " --json --quiet");
  const auto surface = surfaces::make_builtin(name);
  const auto expected = surface->expected_topology();
  const auto& a = j["analysis"];
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(a["euler_characteristic"], expected.euler_characteristic);
  EXPECT_EQ(a["boundary_loops"], expected.boundary_loops);
  const double diagonal = surfaces::bbox_diagonal(*surface);
  const double gap = boundary_gap(*surface, io::read_points(path("p.xyz")).points) / diagonal;
  const double bar = std::max(0.005, 1.1 * gap);
  // The report gives the same gap (the reference's curves have vertices 2e-3 diagonals
  // apart; it measures at steps of 1e-4).
  EXPECT_NEAR(a["reference_boundary_gap"]["max_rel_diag"].get<double>(), gap, 2e-4);
  const double mesh_to_truth = a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>();
  const double truth_to_mesh = a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>();
  std::cout << name << " seed " << seed << " noise " << noise << ": mesh->truth " << 100 * mesh_to_truth
            << "%, truth->mesh " << 100 * truth_to_mesh << "% (bar " << 100 * bar << "%)\n";
  EXPECT_LT(mesh_to_truth, 0.005);
  EXPECT_LT(truth_to_mesh, bar);
}

// Small islands beside a large sheet (specks of a scan): flat discs of radius 0.15 and 0.1,
// 0.2 above and below the plane of the square [-1, 1]^2 and 0.35 and 0.4 beyond its edges,
// sampled as densely. The automatic rho (about 0.17, the diagonal's cap) exceeds their radii,
// so their rims (0.94 and 0.63 long) are shorter than the 2 pi rho the envelope resolves; the
// sheet still follows them, and each island comes out as a disc with its rim. Before, the
// larger came out as a closed, doubled disc (its rim filled as a hole below the resolution)
// and the smaller, under 1% of the area, was dropped as a crumb of the sheet.
TEST_F(CliTest, small_islands_come_out_as_discs_not_closed_shells_nor_dropped) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointSet points;
  for (int i = 0; i < 10000; ++i) points.points.emplace_back(2 * u(rng) - 1, 2 * u(rng) - 1, 0.0);
  struct Island {
    Point3 centre;
    double radius;
  };
  const std::vector<Island> islands{{Point3(1.5, 0.0, 0.2), 0.15}, {Point3(0.0, 1.5, -0.2), 0.1}};
  for (const Island& island : islands) {
    const auto count = static_cast<int>(10000 * std::numbers::pi * island.radius * island.radius / 4);  // same density
    for (int i = 0; i < count; ++i) {
      const double r = island.radius * std::sqrt(u(rng)), a = 2 * std::numbers::pi * u(rng);
      points.points.emplace_back(island.centre.x() + r * std::cos(a), island.centre.y() + r * std::sin(a),
                                 island.centre.z());
    }
  }
  io::write_points(path("p.xyz"), points);
  const auto j = run_envcrust_json("reconstruct " + path("p.xyz") + " -o " + path("m.ply") + " --json --quiet");
  const auto& a = j["analysis"];
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(a["euler_characteristic"], 3);  // three discs
  ASSERT_EQ(a["component_list"].size(), 3u);
  for (const auto& c : a["component_list"]) {
    EXPECT_EQ(c["euler_characteristic"], 1);
    EXPECT_EQ(c["boundary_loops"], 1);
  }
  std::vector<double> lengths;
  for (const auto& loop : a["loops"]) lengths.push_back(loop["length"].get<double>());
  std::sort(lengths.begin(), lengths.end());
  ASSERT_EQ(lengths.size(), 3u);
  EXPECT_NEAR(lengths[0], 2 * std::numbers::pi * 0.1, 0.1);  // the samples stop short of the rims
  EXPECT_NEAR(lengths[1], 2 * std::numbers::pi * 0.15, 0.1);
  EXPECT_NEAR(lengths[2], 8.0, 0.2);
  // The islands' faces lie in their planes and within their rims.
  const TriangleMesh mesh = io::read_triangle_mesh(path("m.ply"));
  std::vector<std::size_t> on_island(islands.size(), 0);
  for (const Point3& p : mesh.vertices) {
    for (std::size_t k = 0; k < islands.size(); ++k) {
      const Island& island = islands[k];
      if (std::abs(p.z() - island.centre.z()) > 0.1) continue;
      ++on_island[k];
      EXPECT_NEAR(p.z(), island.centre.z(), 1e-3);
      EXPECT_LT(std::hypot(p.x() - island.centre.x(), p.y() - island.centre.y()), island.radius + 1e-3);
    }
  }
  for (const std::size_t n : on_island) EXPECT_GT(n, 30u);
  for (const auto& w : j["warnings"]) EXPECT_EQ(w.get<std::string>().find("closed in the result"), std::string::npos) << w;
}

INSTANTIATE_TEST_SUITE_P(Surfaces, PointFileAccuracy,
                         ::testing::Values(Case{"cylinder", 1, 0.0}, Case{"trefoil-ribbon", 1, 0.0},
                                           Case{"unknot-ribbon", 1, 0.0}, Case{"moebius", 3, 0.0025},
                                           Case{"unknot-ribbon", 3, 0.0025}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string label = std::get<0>(info.param) + (std::get<2>(info.param) > 0 ? "_noisy" : "");
                           for (char& c : label) c = c == '-' ? '_' : c;
                           return label;
                         });

}  // namespace
}  // namespace envcrust::testing
