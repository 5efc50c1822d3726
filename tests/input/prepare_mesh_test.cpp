// Tests of input::prepare_mesh: a disc, an annulus and a cylinder give their border loops and
// topology, a triangle soup is welded back into one piece, a folded sheet's crease is rounded
// off or joined, vertex attributes reach the output's side, and the exact refusals.
#include "fixtures/shapes.h"

#include "envcrust/errors.h"
#include "envcrust/input.h"
#include "input/expect_refusal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace envcrust {
namespace {

bool has_note(const input::PreparedInput& prepared, const std::string& note) {
  for (const auto& n : prepared.notes)
    if (n == note) return true;
  return false;
}

struct MeshCase {
  std::string name;
  TriangleMesh mesh;
  std::size_t loops;
  bool is_orientable;
  long genus;
};

TEST(PrepareMesh, border_loops_and_topology_of_small_meshes) {
  const std::vector<MeshCase> cases = {{"square", fixtures::square(4), 1, true, 0},
                                       {"annulus", fixtures::annulus(), 2, true, 0},
                                       {"open cylinder", fixtures::open_cylinder(), 2, true, 0},
                                       {"moebius", fixtures::moebius(), 1, false, 1}};
  for (const auto& c : cases) {
    const auto prepared = input::prepare_mesh(c.mesh);
    EXPECT_EQ(prepared.samples.boundary.size(), c.loops) << c.name;
    ASSERT_TRUE(prepared.kind.is_orientable.has_value()) << c.name;
    EXPECT_EQ(*prepared.kind.is_orientable, c.is_orientable) << c.name;
    ASSERT_TRUE(prepared.kind.genus.has_value()) << c.name;
    EXPECT_EQ(*prepared.kind.genus, c.genus) << c.name;
    EXPECT_FALSE(prepared.kind.is_builtin) << c.name;
    // Every vertex (all used, none of zero normal) and every face centre is a sample.
    EXPECT_EQ(prepared.samples.points.size(), c.mesh.vertices.size() + c.mesh.triangles.size()) << c.name;
    EXPECT_TRUE(has_note(prepared, "mesh vertices and face centres; " + std::to_string(c.loops) + " border loops"))
        << c.name;
  }
}

TEST(PrepareMesh, a_triangle_soup_is_welded_into_one_disc) {
  const TriangleMesh square = fixtures::square(4);  // 25 vertices, 32 faces
  const auto prepared = input::prepare_mesh(fixtures::as_soup(square));
  EXPECT_TRUE(has_note(prepared, "71 vertices at the coordinates of another welded to it"));
  EXPECT_EQ(prepared.samples.boundary.size(), 1u);
  EXPECT_EQ(prepared.samples.points.size(), 25u + 32u);
}

// Two unit squares bent by 90 degrees along a 1-unit fold (a tenth of the diagonal is 0.17).
TEST(PrepareMesh, a_folded_sheets_crease_is_rounded_off_or_joined) {
  const TriangleMesh sheet = fixtures::folded_sheet(90.0);
  const auto rounded = input::prepare_mesh(sheet);
  EXPECT_TRUE(rounded.samples.creases.empty());
  ASSERT_EQ(rounded.notes.size(), 2u);
  EXPECT_EQ(rounded.notes[1].rfind("the mesh bends by more than 80 degrees across 20 edges (1 long in all", 0), 0u)
      << rounded.notes[1];

  input::InputOptions join;
  join.creases = input::CreaseMode::Join;
  const auto joined = input::prepare_mesh(sheet, join);
  EXPECT_EQ(joined.samples.creases.size(), 20u);
  // Rounded off, the fitted normal lines turn across the fold where the faces' own jump.
  ASSERT_EQ(joined.samples.normals.size(), rounded.samples.normals.size());
  std::size_t turned = 0;
  for (std::size_t i = 0; i < joined.samples.normals.size(); ++i)
    turned += std::abs(joined.samples.normals[i] * rounded.samples.normals[i]) < std::cos(10.0 * M_PI / 180.0);
  EXPECT_GT(turned, 0u);
}

// The used vertices keep their colours and scalars, at their own positions in the samples'
// frame (here a local origin far from (0, 0, 0)); a vertex no face uses is no point of M.
TEST(PrepareMesh, vertex_attributes_follow_the_used_vertices_into_the_samples_frame) {
  const Vector3 far(500000, 5000000, 0);
  input::MeshInput in;
  in.mesh = fixtures::square(2);  // 9 vertices, all used
  for (Point3& v : in.mesh.vertices) v = v + far;
  in.mesh.vertices.push_back(Point3(9, 9, 9) + far);  // used by no face
  const std::size_t n = in.mesh.vertices.size();
  in.vertex_attributes.names = {"intensity"};
  in.vertex_attributes.scalars.resize(1);
  for (std::size_t v = 0; v < n; ++v) {
    in.vertex_attributes.colours.push_back({static_cast<std::uint8_t>(10 * v), 0, 255});
    in.vertex_attributes.scalars[0].push_back(static_cast<float>(v));
  }
  const TriangleMesh input_mesh = in.mesh;
  const auto prepared = input::prepare_mesh(std::move(in));
  ASSERT_NE(prepared.origin, CGAL::NULL_VECTOR);
  ASSERT_EQ(prepared.attribute_points.size(), n - 1);
  ASSERT_EQ(prepared.attributes.colours.size(), n - 1);
  ASSERT_EQ(prepared.attributes.scalars.size(), 1u);
  EXPECT_EQ(prepared.attributes.names, std::vector<std::string>{"intensity"});
  for (std::size_t i = 0; i < n - 1; ++i) {
    const std::size_t v = static_cast<std::size_t>(prepared.attributes.scalars[0][i]);
    EXPECT_EQ(prepared.attributes.colours[i][0], 10 * v);
    EXPECT_LT(CGAL::squared_distance(prepared.attribute_points[i] + prepared.origin, input_mesh.vertices[v]), 1e-12);
  }
}

TEST(PrepareMesh, refusals_start_with_the_inputs_name) {
  input::InputOptions options;
  options.name = "m.off";
  expect_refusal<InvalidInput>([&] { input::prepare_mesh(TriangleMesh{}, options); },
                  "m.off: the mesh has no faces");
  TriangleMesh twice;
  twice.vertices = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)};
  twice.triangles = {{0, 0, 1}, {1, 2, 2}};
  expect_refusal<InvalidInput>([&] { input::prepare_mesh(twice, options); },
                  "m.off: the mesh has no faces but 2 that use a vertex twice");
  TriangleMesh flat;  // a face on a line, and again reversed: no area, no normal
  flat.vertices = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(2, 0, 0)};
  flat.triangles = {{0, 1, 2}, {0, 2, 1}};
  expect_refusal<InvalidInput>([&] { input::prepare_mesh(flat, options); },
                  "m.off: the mesh has no face of positive area");
  TriangleMesh fin;  // three triangles on the edge (0, 1)
  fin.vertices = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, -1, 0), Point3(0, 0, 1)};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  expect_refusal<input::NotASurface>([&] { input::prepare_mesh(fin, options); },
                  "m.off: edge (0, 1) has 3 faces: the mesh is not a surface");
  input::MeshInput short_colours{fixtures::square(1), {}};
  short_colours.vertex_attributes.colours.resize(3);
  expect_refusal<InvalidInput>([&] { input::prepare_mesh(short_colours, options); },
                  "m.off: the vertex colours number 3 for 4 vertices");
  input::MeshInput long_scalars{fixtures::square(1), {}};
  long_scalars.vertex_attributes.names = {"intensity"};
  long_scalars.vertex_attributes.scalars = {std::vector<float>(5, 1.0F)};
  expect_refusal<InvalidInput>([&] { input::prepare_mesh(long_scalars, options); },
                  "m.off: the vertex values of 'intensity' number 5 for 4 vertices");
}

}  // namespace
}  // namespace envcrust
