// The Power Crust's 64-byte Delaunay cell (conflict flag in a vertex pointer's low bits)
// gives the same triangulation as CGAL's own cell, sequential and lock-grid parallel.
#include "delaunay.h"
#include "support.h"

#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <random>
#include <set>

using namespace envcrust;
using namespace envcrust::powercrust;

namespace {

using Cell = std::array<Index, 4>;

template <class Dt>
std::set<Cell> cells_by_vertex_ids(const Dt& dt) {
  std::set<Cell> out;
  for (auto c : dt.finite_cell_handles()) {
    Cell ids{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()};
    std::sort(ids.begin(), ids.end());
    out.insert(ids);
  }
  return out;
}

// CGAL's default cell, the reference.
std::set<Cell> reference_cells(const std::vector<Point3>& samples, const std::array<Point3, 8>& corners) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
  CGAL::Delaunay_triangulation_3<Kernel, Tds> dt;
  std::vector<std::pair<Point3, Index>> input;
  for (std::size_t i = 0; i < samples.size(); ++i) input.emplace_back(samples[i], static_cast<Index>(i));
  for (std::size_t k = 0; k < corners.size(); ++k)
    input.emplace_back(corners[k], static_cast<Index>(samples.size() + k));
  dt.insert(input.begin(), input.end());
  return cells_by_vertex_ids(dt);
}

void expect_same_triangulation(const std::vector<Point3>& samples) {
  const auto corners = bounding_points(samples, 4.0);
  const std::set<Cell> expected = reference_cells(samples, corners);
  for (bool parallel : {false, true}) {
    const auto dt = build_delaunay(samples, corners, parallel);
    EXPECT_TRUE(dt->is_valid()) << "parallel " << parallel;
    EXPECT_EQ(cells_by_vertex_ids(*dt), expected) << "parallel " << parallel;
    // The conflict flags are all clear again after the insertion (their bits share the
    // first vertex pointer: a stale bit would misread as a vertex).
    for (auto c : dt->all_cell_handles()) EXPECT_TRUE(c->tds_data().is_clear());
  }
}

}  // namespace

TEST(PowerCrustCompactCell, is_64_bytes_and_triangulates_like_cgals_cell) {
  EXPECT_EQ(sizeof(Delaunay::Cell), 64u);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point3> points(3000);
  for (auto& p : points) p = Point3(u(rng), u(rng), u(rng));
  expect_same_triangulation(points);
  expect_same_triangulation(test_support::sample_builtin("torus", 3000, 0.0));
}

TEST(PowerCrustCompactCell, degenerate_grid_triangulates_like_cgals_cell) {
  // A regular grid: every unit cube's 8 corners are cospherical, so the cells come from
  // CGAL's symbolic perturbation, which must not depend on the cell layout.
  std::vector<Point3> grid;
  for (int x = 0; x < 9; ++x)
    for (int y = 0; y < 9; ++y)
      for (int z = 0; z < 9; ++z) grid.emplace_back(x, y, z);
  expect_same_triangulation(grid);
}
