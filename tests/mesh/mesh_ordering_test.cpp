// order_spatially: the same mesh renumbered, neighbours close in the new numbering.
#include "envcrust/mesh.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>

using namespace envcrust;

TEST(OrderSpatially, renumbers_the_same_triangles_and_brings_neighbours_close) {
  TriangleMesh input = fixtures::square(40);
  // Shuffle the vertices: an order unrelated to space, as a sheet of Voronoi vertices has.
  std::vector<Index> shuffled(input.vertices.size());
  for (Index i = 0; i < shuffled.size(); ++i) shuffled[i] = i;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  TriangleMesh mesh;
  mesh.vertices.resize(input.vertices.size());
  for (Index i = 0; i < shuffled.size(); ++i) mesh.vertices[shuffled[i]] = input.vertices[i];
  for (const auto& t : input.triangles) mesh.triangles.push_back({shuffled[t[0]], shuffled[t[1]], shuffled[t[2]]});

  const auto ordered = mesh::order_spatially(mesh);
  ASSERT_EQ(ordered.mesh.vertices.size(), mesh.vertices.size());
  ASSERT_EQ(ordered.old_vertex.size(), mesh.vertices.size());
  std::set<Index> sources(ordered.old_vertex.begin(), ordered.old_vertex.end());
  EXPECT_EQ(sources.size(), mesh.vertices.size());  // a permutation
  for (std::size_t v = 0; v < ordered.mesh.vertices.size(); ++v)
    EXPECT_EQ(ordered.mesh.vertices[v], mesh.vertices[ordered.old_vertex[v]]);
  // The same triangles with the same windings, mapped back to the old numbers.
  std::multiset<std::array<Index, 3>> before, after;
  auto rotated = [](std::array<Index, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());  // keeps the winding
    return t;
  };
  for (const auto& t : mesh.triangles) before.insert(rotated(t));
  for (const auto& t : ordered.mesh.triangles)
    after.insert(rotated({ordered.old_vertex[t[0]], ordered.old_vertex[t[1]], ordered.old_vertex[t[2]]}));
  EXPECT_EQ(before, after);
  // Faces follow their smallest vertex number.
  auto smallest = [](const std::array<Index, 3>& t) { return std::min({t[0], t[1], t[2]}); };
  EXPECT_TRUE(std::is_sorted(ordered.mesh.triangles.begin(), ordered.mesh.triangles.end(),
                             [&](const auto& a, const auto& b) { return smallest(a) < smallest(b); }));
  // Neighbours close in memory: the median index gap along edges drops from about a quarter
  // of the vertex count (shuffled) to about the grid's side (41 here) or less.
  auto median_gap = [](const TriangleMesh& m) {
    std::vector<double> gaps;
    for (const auto& t : m.triangles)
      for (int i = 0; i < 3; ++i) gaps.push_back(std::abs(double(t[i]) - double(t[(i + 1) % 3])));
    std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
    return gaps[gaps.size() / 2];
  };
  EXPECT_GT(median_gap(mesh), 200.0);
  EXPECT_LE(median_gap(ordered.mesh), 41.0);
}
