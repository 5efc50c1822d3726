// Tests of join_open_arcs: open arcs of a flagged band joined end to end into closed loops.
#include "boundary_detail.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace envcrust {
namespace {

using boundary::detail::Centreline;

// An arc of the circle of radius `radius` about `centre` (z = 0) from angle a0 to a1, points
// about `step` apart, appended to `points`; its centreline and component (indices).
struct Arcs {
  std::vector<Point3> points;
  std::vector<std::vector<std::size_t>> components;
  std::vector<Centreline> lines;

  void add(double cx, double cy, double radius, double a0, double a1, double step, bool reversed = false) {
    const auto n = static_cast<std::size_t>(std::ceil(std::abs(a1 - a0) * radius / step));
    Centreline line;
    std::vector<std::size_t> component;
    for (std::size_t k = 0; k <= n; ++k) {
      const double t = reversed ? 1.0 - static_cast<double>(k) / n : static_cast<double>(k) / n;
      const double a = a0 + t * (a1 - a0);
      component.push_back(points.size());
      points.emplace_back(cx + radius * std::cos(a), cy + radius * std::sin(a), 0.0);
      line.points.push_back(points.back());
    }
    std::sort(component.begin(), component.end());
    for (std::size_t k = 0; k + 1 < line.points.size(); ++k)
      line.open_length += std::sqrt(CGAL::squared_distance(line.points[k], line.points[k + 1]));
    line.end_gap = std::sqrt(CGAL::squared_distance(line.points.front(), line.points.back()));
    line.length = line.open_length + line.end_gap;
    components.push_back(std::move(component));
    lines.push_back(std::move(line));
  }
};

boundary::detail::ArcJoinLimits limits() {
  return {.close_gap = 0.25, .min_arc = 0.5, .max_join = 0.5, .max_join_local = 0.0};
}

// A unit circle flagged as four arcs with gaps of 0.3 (one of them walked backwards), and an
// arc of another circle far away: the four become one loop, walked consistently, the fifth
// stays as it was.
TEST(JoinOpenArcs, FourArcsOfACircleMakeOneLoop) {
  Arcs arcs;
  const double gap = 0.3;  // radians = length on the unit circle
  for (int q = 0; q < 4; ++q) {
    const double a0 = q * M_PI / 2 + gap / 2, a1 = (q + 1) * M_PI / 2 - gap / 2;
    arcs.add(0, 0, 1, a0, a1, 0.05, q == 2);
  }
  arcs.add(10, 0, 1, 0.0, 3.0, 0.05);
  const boundary::detail::PointIndex index(arcs.points);
  const std::size_t made = boundary::detail::join_open_arcs(arcs.components, arcs.lines, arcs.points, index, limits());
  EXPECT_EQ(made, 1u);
  ASSERT_EQ(arcs.lines.size(), 2u);
  ASSERT_EQ(arcs.components.size(), 2u);
  const Centreline& loop = arcs.lines[0];
  EXPECT_EQ(loop.joined_arcs, 4u);
  EXPECT_NEAR(loop.join_gap, 2 * std::sin(gap / 2), 1e-9);
  // Every step of the loop, the closing one too, is a step along an arc or across a gap.
  for (std::size_t k = 0; k < loop.points.size(); ++k) {
    const double step = std::sqrt(CGAL::squared_distance(loop.points[k], loop.points[(k + 1) % loop.points.size()]));
    EXPECT_LT(step, 0.31) << "step " << k;
  }
  EXPECT_NEAR(loop.length, 2 * M_PI, 0.01);
  EXPECT_NEAR(loop.open_length, loop.length - loop.end_gap, 1e-12);
  // The loop's component holds the four arcs' points, sorted; the far arc is untouched.
  std::vector<std::size_t> expected(arcs.points.size() - arcs.components[1].size());
  std::iota(expected.begin(), expected.end(), std::size_t{0});
  EXPECT_EQ(arcs.components[0], expected);
  EXPECT_EQ(arcs.lines[1].joined_arcs, 0u);
  EXPECT_EQ(arcs.lines[1].points.size(), arcs.components[1].size());
}

// Joins must be shorter in all than the arcs' own closing gaps: two nearly closed circles of
// radius 0.2 whose gaps face each other close better alone (gaps 0.118 each) than joined
// (joins 0.168 each).
TEST(JoinOpenArcs, KeepsArcsThatCloseBetterAlone) {
  Arcs arcs;
  arcs.add(0, 0, 0.2, 0.3, 2 * M_PI - 0.3, 0.02);
  arcs.add(0.55, 0, 0.2, M_PI + 0.3, 3 * M_PI - 0.3, 0.02);
  const boundary::detail::PointIndex index(arcs.points);
  auto l = limits();
  l.close_gap = 0.1, l.min_arc = 0.1;
  EXPECT_EQ(boundary::detail::join_open_arcs(arcs.components, arcs.lines, arcs.points, index, l), 0u);
  EXPECT_EQ(arcs.lines.size(), 2u);
  // Moved closer (joins 0.018 each), they make one loop.
  Arcs near;
  near.add(0, 0, 0.2, 0.3, 2 * M_PI - 0.3, 0.02);
  near.add(0.4, 0, 0.2, M_PI + 0.3, 3 * M_PI - 0.3, 0.02);
  const boundary::detail::PointIndex near_index(near.points);
  EXPECT_EQ(boundary::detail::join_open_arcs(near.components, near.lines, near.points, near_index, l), 1u);
}

// A join may reach max_join_local times the local spacing (6th-neighbour distance) at its
// ends where that exceeds max_join: a rim sampled more sparsely than the average.
TEST(JoinOpenArcs, LongerJoinsWhereTheRimIsSparse) {
  Arcs arcs;
  const double gap = 0.6;
  for (int h = 0; h < 2; ++h) arcs.add(0, 0, 1, h * M_PI + gap / 2, (h + 1) * M_PI - gap / 2, 0.1);
  const boundary::detail::PointIndex index(arcs.points);
  auto strict = limits();  // joins of 0.59 > max_join 0.5: nothing joined
  auto copy = arcs;
  EXPECT_EQ(boundary::detail::join_open_arcs(copy.components, copy.lines, copy.points, index, strict), 0u);
  auto local = strict;  // the 6th neighbour of an arc end lies 0.6 away: 5 x 0.6 = 3
  local.max_join_local = 5.0;
  EXPECT_EQ(boundary::detail::join_open_arcs(arcs.components, arcs.lines, arcs.points, index, local), 1u);
  ASSERT_EQ(arcs.lines.size(), 1u);
  EXPECT_EQ(arcs.lines[0].joined_arcs, 2u);
}

// Or max_join_rel_arc times the shorter of its two arcs: a rim flagged in long pieces.
TEST(JoinOpenArcs, LongerJoinsBetweenLongArcs) {
  Arcs arcs;
  const double gap = 0.6;
  for (int h = 0; h < 2; ++h) arcs.add(0, 0, 1, h * M_PI + gap / 2, (h + 1) * M_PI - gap / 2, 0.05);
  const boundary::detail::PointIndex index(arcs.points);
  auto l = limits();  // joins of 0.59 > max_join 0.5; the arcs are 2.54 long
  l.max_join_rel_arc = 0.2;  // 0.51: still nothing joined
  auto copy = arcs;
  EXPECT_EQ(boundary::detail::join_open_arcs(copy.components, copy.lines, copy.points, index, l), 0u);
  l.max_join_rel_arc = 0.25;  // 0.64
  EXPECT_EQ(boundary::detail::join_open_arcs(arcs.components, arcs.lines, arcs.points, index, l), 1u);
  ASSERT_EQ(arcs.lines.size(), 1u);
  EXPECT_EQ(arcs.lines[0].joined_arcs, 2u);
}

// A chain of arcs that no join closes is still one loop, closed across the gap between its
// free ends, when its joins and that gap are shorter in all than the arcs' own closing gaps:
// a unit circle flagged as four arcs, three gaps of 0.3 and one of 1.2 (beyond max_join).
TEST(JoinOpenArcs, ChainClosedAcrossItsWidestGap) {
  Arcs arcs;
  const double small = 0.3, wide = 1.2;
  double a = wide / 2;
  for (int q = 0; q < 4; ++q) {
    const double span = (2 * M_PI - wide - 3 * small) / 4;
    arcs.add(0, 0, 1, a, a + span, 0.05, q == 1);
    a += span + small;
  }
  const boundary::detail::PointIndex index(arcs.points);
  EXPECT_EQ(boundary::detail::join_open_arcs(arcs.components, arcs.lines, arcs.points, index, limits()), 1u);
  ASSERT_EQ(arcs.lines.size(), 1u);
  const Centreline& loop = arcs.lines[0];
  EXPECT_EQ(loop.joined_arcs, 4u);
  EXPECT_NEAR(loop.join_gap, 2 * std::sin(small / 2), 1e-9);
  EXPECT_NEAR(loop.end_gap, 2 * std::sin(wide / 2), 1e-9);
  // Around the circle, with the wide gap's chord for its arc.
  EXPECT_NEAR(loop.length, 2 * M_PI - wide + 2 * std::sin(wide / 2), 0.01);
  EXPECT_EQ(arcs.components[0].size(), arcs.points.size());
}

// A chain whose free ends lie far apart stays apart: two half circles of radius 1, side by
// side, whose near ends are 0.3 apart; joined, the loop would close across 4.3, more than
// their own gaps of 2 each.
TEST(JoinOpenArcs, ChainKeptApartWhenItsEndsAreFar) {
  Arcs arcs;
  arcs.add(0, 0, 1, 0.0, M_PI, 0.05);
  arcs.add(2.3, 0, 1, M_PI, 2 * M_PI, 0.05);
  const boundary::detail::PointIndex index(arcs.points);
  EXPECT_EQ(boundary::detail::join_open_arcs(arcs.components, arcs.lines, arcs.points, index, limits()), 0u);
  ASSERT_EQ(arcs.lines.size(), 2u);
  EXPECT_EQ(arcs.lines[0].joined_arcs, 0u);
  EXPECT_EQ(arcs.lines[1].joined_arcs, 0u);
}

}  // namespace
}  // namespace envcrust
