// Tests of PointAttributes::pick and attributes::carry_nearest (colours and scalars carried
// from input points to the vertices of a mesh).
#include "envcrust/attributes.h"

#include <gtest/gtest.h>

namespace envcrust {
namespace {

PointAttributes three_points() {
  PointAttributes a;
  a.colours = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  a.names = {"intensity"};
  a.scalars = {{1.0F, 2.0F, 3.0F}};
  return a;
}

TEST(PointAttributes, pick_selects_and_reorders_colours_and_scalars) {
  const PointAttributes picked = three_points().pick({2, 0, 0});
  EXPECT_EQ(picked.colours, (std::vector<Colour>{{0, 0, 255}, {255, 0, 0}, {255, 0, 0}}));
  EXPECT_EQ(picked.names, std::vector<std::string>{"intensity"});
  EXPECT_EQ(picked.scalars[0], (std::vector<float>{3.0F, 1.0F, 1.0F}));
  EXPECT_TRUE(PointAttributes{}.pick({0, 1}).empty());
}

TEST(PointAttributes, each_target_takes_the_attributes_of_its_nearest_source) {
  const std::vector<Point3> sources = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)};
  const std::vector<Point3> targets = {Point3(0.9, 0.2, 0), Point3(0.1, 0.1, 5), Point3(-1, 2, 0)};
  EXPECT_EQ(attributes::nearest_sources(sources, targets), (std::vector<std::size_t>{1, 0, 2}));
  const PointAttributes carried = attributes::carry_nearest(sources, three_points(), targets);
  EXPECT_EQ(carried.colours, (std::vector<Colour>{{0, 255, 0}, {255, 0, 0}, {0, 0, 255}}));
  EXPECT_EQ(carried.scalars[0], (std::vector<float>{2.0F, 1.0F, 3.0F}));
  // nothing to carry: no attributes, or no source points
  EXPECT_TRUE(attributes::carry_nearest(sources, PointAttributes{}, targets).empty());
  EXPECT_TRUE(attributes::carry_nearest({}, three_points(), targets).empty());
}

}  // namespace
}  // namespace envcrust
