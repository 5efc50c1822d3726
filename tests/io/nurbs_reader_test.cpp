// Reading NURBS patches: IGES entity 128 (with a transformation matrix), NURBS-Python JSON,
// and the files refused.
#include "envcrust/io.h"
#include "fixtures/nurbs_patches.h"
#include "io_test_support.h"

#include <cmath>
#include <sstream>
#include <string>

namespace envcrust::io {
namespace {

using testing::io_error_of;
namespace fixtures = envcrust::testing;

class NurbsReader : public testing::TempDirTest {};

// The file's one patch.
surfaces::NurbsPatch read_nurbs_patch(const std::filesystem::path& path) {
  auto patches = read_nurbs_patches(path);
  EXPECT_EQ(patches.size(), 1u) << path;
  return patches.empty() ? surfaces::NurbsPatch{} : std::move(patches.front());
}

void expect_same_patch(const surfaces::NurbsPatch& expected, const surfaces::NurbsPatch& actual) {
  EXPECT_EQ(expected.degree_u, actual.degree_u);
  EXPECT_EQ(expected.degree_v, actual.degree_v);
  EXPECT_EQ(expected.count_u, actual.count_u);
  EXPECT_EQ(expected.count_v, actual.count_v);
  EXPECT_EQ(expected.knots_u, actual.knots_u);
  EXPECT_EQ(expected.knots_v, actual.knots_v);
  EXPECT_EQ(expected.weights, actual.weights);
  ASSERT_EQ(expected.control_points.size(), actual.control_points.size());
  for (std::size_t k = 0; k < expected.control_points.size(); ++k)
    testing::expect_same_point(expected.control_points[k], actual.control_points[k]);
}

TEST_F(NurbsReader, reads_an_iges_surface_exactly_with_its_parameter_range) {
  const auto sphere = fixtures::sphere_patch();
  for (const char* name : {"s.igs", "S.IGES"}) {
    const auto patch = read_nurbs_patch(write(name, fixtures::iges_text(sphere)));
    expect_same_patch(sphere, patch);
    ASSERT_TRUE(patch.parameter_range.has_value());
    EXPECT_EQ(*patch.parameter_range, (std::array<double, 4>{0, 1, 0, 1}));
  }
}

TEST_F(NurbsReader, reads_an_iges_file_without_a_global_section_with_the_default_delimiters) {
  const auto sphere = fixtures::sphere_patch();
  std::istringstream in(fixtures::iges_text(sphere));
  std::string text, line;
  while (std::getline(in, line))
    if (line.size() < 73 || line[72] != 'G') text += line + "\n";
  expect_same_patch(sphere, read_nurbs_patch(write("no-g.igs", text)));
}

TEST_F(NurbsReader, reads_fortran_style_iges_numbers) {
  const auto cylinder = fixtures::cylinder_patch();
  std::string text = fixtures::iges_text(cylinder);
  // Same width, other spellings: no leading zero, a plus sign, D and E exponents.
  const std::string plain = "0.25,0.25,0.5,0.5,0.75,0.75", odd = ".25,+.25,.5D0,.5,7.5D-1,.75";
  ASSERT_NE(text.find(plain), std::string::npos);
  text.replace(text.find(plain), plain.size(), odd);
  expect_same_patch(cylinder, read_nurbs_patch(write("c.igs", text)));
}

TEST_F(NurbsReader, places_an_iges_surface_by_its_transformation_matrix) {
  const auto cylinder = fixtures::cylinder_patch();
  // A quarter turn about z, then a shift by (5, 0, -2).
  const std::array<double, 12> matrix{0, -1, 0, 5, 1, 0, 0, 0, 0, 0, 1, -2};
  const auto patch = read_nurbs_patch(write("c.igs", fixtures::iges_text(cylinder, matrix)));
  ASSERT_EQ(patch.control_points.size(), cylinder.control_points.size());
  for (std::size_t k = 0; k < patch.control_points.size(); ++k) {
    const Point3& q = cylinder.control_points[k];
    testing::expect_same_point(Point3(5 - q.y(), q.x(), q.z() - 2), patch.control_points[k]);
  }
}

TEST_F(NurbsReader, reads_nurbs_python_json_listed_v_fastest) {
  const auto band = fixtures::moebius_patch();
  const auto patch = read_nurbs_patch(write("band.json", fixtures::geomdl_json(band)));
  expect_same_patch(band, patch);
  EXPECT_FALSE(patch.parameter_range.has_value());
  // Weights are optional: without them the patch is polynomial.
  const auto plain = read_nurbs_patch(write(
      "plain.json", R"({"shape": {"type": "surface", "data": [{"degree_u": 1, "degree_v": 1, "size_u": 2, "size_v": 2,
        "knotvector_u": [0, 0, 1, 1], "knotvector_v": [0, 0, 1, 1],
        "control_points": {"points": [[0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 1]]}}]}})"));
  EXPECT_EQ(plain.weights, std::vector<double>(4, 1.0));
  testing::expect_same_point(Point3(0, 1, 0), plain.control_points[2]);  // (i 0, j 1)
  testing::expect_same_point(Point3(1, 0, 0), plain.control_points[1]);  // (i 1, j 0)
}

TEST_F(NurbsReader, reads_an_iges_trimmed_surface_trimmed_along_its_own_border) {
  const auto sphere = fixtures::sphere_patch();  // domain [0, 1] x [0, 1]
  // N1 = 0: the outer boundary is the domain's border by definition.
  expect_same_patch(sphere, read_nurbs_patch(write("n1.igs", fixtures::iges_trimmed_text(sphere))));
  // The border traced by lines and a degree-1 B-spline curve (126), in pieces of any length.
  // K 1, degree 1, flags, knots 0 0 1 1, weights 1 1, points (0, 0, 0) (0.5, 0, 0), range, normal.
  const fixtures::IgesEntity spline{126, {"1", "1", "1", "0", "1", "0", "0", "0", "1", "1", "1", "1", "0", "0", "0",
                                          "0.5", "0", "0", "0", "1", "0", "0", "1"}, 0};
  const auto traced = fixtures::iges_trimmed_text(
      sphere, {spline, fixtures::iges_line(0.5, 0, 1, 0), fixtures::iges_line(1, 0, 1, 1), fixtures::iges_line(1, 1, 0, 1),
               fixtures::iges_line(0, 1, 0, 0)});
  expect_same_patch(sphere, read_nurbs_patch(write("traced.igs", traced)));
}

TEST_F(NurbsReader, reads_the_trimming_loops_of_an_iges_trimmed_surface) {
  const auto square = fixtures::square_patch();
  // An outer boundary inside the domain: one loop of four lines.
  const auto inner = read_nurbs_patch(write(
      "inner.igs", fixtures::iges_trimmed_text(square, {fixtures::iges_line(0.1, 0.1, 0.9, 0.1),
                                                        fixtures::iges_line(0.9, 0.1, 0.9, 0.9),
                                                        fixtures::iges_line(0.9, 0.9, 0.1, 0.9),
                                                        fixtures::iges_line(0.1, 0.9, 0.1, 0.1)})));
  ASSERT_EQ(inner.trim_loops.size(), 1u);
  ASSERT_EQ(inner.trim_loops[0].size(), 4u);
  EXPECT_EQ(inner.trim_loops[0][1].points, (std::vector<std::array<double, 2>>{{0.9, 0.1}, {0.9, 0.9}}));
  // The domain's border (N1 = 0) and a circular hole (entity 100): the border becomes the
  // outer loop, the circle a fine polyline around (0.5, 0.5).
  const auto holed = read_nurbs_patch(
      write("holed.igs", fixtures::iges_trimmed_text(square, {}, {{fixtures::iges_circle(0.5, 0.5, 0.25)}})));
  ASSERT_EQ(holed.trim_loops.size(), 2u);
  EXPECT_EQ(holed.trim_loops[0][0].points.size(), 5u);
  ASSERT_EQ(holed.trim_loops[1].size(), 1u);
  EXPECT_GE(holed.trim_loops[1][0].points.size(), 1024u);
  for (const auto& [u, v] : holed.trim_loops[1][0].points) EXPECT_NEAR(std::hypot(u - 0.5, v - 0.5), 0.25, 1e-12);
  const auto surface = surfaces::make_nurbs_surface(holed, "holed");
  EXPECT_EQ(surface->expected_topology().euler_characteristic, 0);
  EXPECT_EQ(surface->expected_topology().boundary_loops, 2);
}

// Counts and pointers are stored as numbers: one far beyond any file (a cast of 1e300 to an
// integer would be undefined) is refused by name.
TEST_F(NurbsReader, refuses_a_count_beyond_any_file) {
  auto text = fixtures::iges_trimmed_text(fixtures::square_patch());
  ASSERT_NE(text.find("144,1,0,0,0;"), std::string::npos);
  text.replace(text.find("144,1,0,0,0;"), 12, "144,1,0,1E9;");  // 1e9 holes, same record width
  const auto file = write("holes.igs", text);
  const std::string message = io_error_of([&] { (void)read_nurbs_patch(file); });
  EXPECT_NE(message.find(": its hole count is 1e+09, not a whole number from 0 to 1e+06"), std::string::npos) << message;
  EXPECT_EQ(message.rfind(file.string() + ": entity 144", 0), 0u) << message;
}

TEST_F(NurbsReader, refuses_trimming_curves_it_cannot_place) {
  const auto square = fixtures::square_patch();
  auto text = fixtures::iges_trimmed_text(square, {fixtures::iges_line(0, 0, 1, 0)});
  // The curve on surface without its parameter-plane curve (BPTR 0).
  text.replace(text.find("142,1,1,7,0,1;"), 14, "142,1,1,0,0,1;");
  auto file = write("space.igs", text);
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ": the outer boundary (entity 142 (directory line 5)) is given in space only, with no "
                            "parameter-plane curve: not supported");
  auto placed = fixtures::iges_line(0.1, 0.1, 0.9, 0.1);
  placed.transform = 1;  // any matrix: a trimming curve is read in the parameter plane as written
  file = write("placed.igs", fixtures::iges_trimmed_text(square, {placed}));
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ": a trimming curve (entity 110 (directory line 9)) placed by a transformation matrix: "
                            "not supported");
  file = write("conic.igs", fixtures::iges_trimmed_text(square, {fixtures::IgesEntity{104, {"1", "0", "1", "0", "0", "-1", "0", "1", "0", "1", "0"}, 0}}));
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ": a trimming curve of IGES entity 104 (lines 110, circular arcs 100, B-spline curves 126 "
                            "and composite curves 102 are read)");
}

TEST_F(NurbsReader, reads_every_surface_of_a_file_in_order) {
  const auto cylinder = fixtures::cylinder_patch();
  const auto from_iges = read_nurbs_patches(write("two.igs", fixtures::iges_text(cylinder, {}, 3)));
  ASSERT_EQ(from_iges.size(), 3u);
  for (const auto& patch : from_iges) expect_same_patch(cylinder, patch);
  // A JSON file's entries in their order: the sphere, then the cylinder.
  const auto from_json = read_nurbs_patches(write("two.json", fixtures::geomdl_json({fixtures::sphere_patch(), cylinder})));
  ASSERT_EQ(from_json.size(), 2u);
  expect_same_patch(fixtures::sphere_patch(), from_json[0]);
  expect_same_patch(cylinder, from_json[1]);
}

TEST_F(NurbsReader, refuses_iges_files_it_cannot_read_whole) {
  const auto cylinder = fixtures::cylinder_patch();
  const std::string text = fixtures::iges_text(cylinder);
  std::string other = text;
  for (std::size_t at = other.find("     128"); at != std::string::npos; at = other.find("     128", at))
    other.replace(at, 8, "     126");
  auto file = write("curve.igs", other);
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ": no rational B-spline surface (IGES entity 128) in the file (its entities: 126)");
  // Cut after the directory and the first parameter line: the parameters end early.
  const std::size_t p2 = text.find("P      2");
  file = write("short.igs", text.substr(0, text.rfind('\n', p2) + 1));
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ": entity 128 (directory line 1) points to parameter lines 1 to 7, but the file has 1");
  file = write("narrow.igs", "128,1,1,1,1;\n");
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ":1: not an IGES record (80 columns with the section letter in column 73)");
  std::string garbled = text;
  garbled.replace(garbled.find("0.25,"), 4, "0.2x");
  file = write("garbled.igs", garbled);
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ": entity 128 at parameter line 1: '0.2x' is not a number");
}

TEST_F(NurbsReader, refuses_json_that_is_not_untrimmed_surfaces) {
  const auto expect_refusal = [&](const std::string& name, const std::string& text, const std::string& problem) {
    const auto file = write(name, text);
    EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }), file.string() + ": " + problem);
  };
  expect_refusal("a.json", "{\"shape\": [1, 2", "invalid JSON: parse error at line 1, column 16: syntax error while parsing array - unexpected end of input; expected ']'");
  expect_refusal("b.json", R"({"shape": {"type": "curve", "data": []}})",
                 "holds a NURBS curve, not a surface (shape.type must be \"surface\")");
  expect_refusal("c.json", R"({"shape": {"type": "surface", "data": [{"degree_v": 1}]}})",
                 "not a NURBS-Python surface: key 'degree_u' not found");
  expect_refusal("d.json", R"({"shape": {"type": "surface", "data": [{}, {}]}})",
                 "surface 1: not a NURBS-Python surface: key 'degree_u' not found");
  expect_refusal("e.json", R"({"shape": {"type": "surface", "data": [{"degree_u": 1, "degree_v": 1, "size_u": 2,
      "size_v": 2, "knotvector_u": [0, 0, 1, 1], "knotvector_v": [0, 0, 1, 1],
      "control_points": {"points": [[0, 0, 0], [0, 1, 0], [1, 0, 0]]}}]}})",
                 "3 control points, size_u x size_v = 2 x 2 expected");
  expect_refusal("f.json", R"({"shape": {"type": "surface", "data": [{"trims": {"data": [{}]}}]}})",
                 "a trimmed surface: NURBS-Python trim curves are not read (an IGES trimmed surface, entity 144, is)");
  expect_refusal("h.json", R"({"shape": {"type": "surface", "data": [{"degree_u": 1, "degree_v": 1, "size_u": -2,
      "size_v": 2, "knotvector_u": [0, 0, 1, 1], "knotvector_v": [0, 0, 1, 1], "control_points": {"points": []}}]}})",
                 "size_u is -2, not a count of 1 to 1000000");
  expect_refusal("i.json", R"({"shape": {"type": "surface", "data": [{"degree_u": 1e999}]}})",
                 "invalid JSON: number overflow parsing '1e999'");
  expect_refusal("j.json", R"({"shape": {"type": "surface", "data": [{"degree_u": 1e20, "degree_v": 1}]}})",
                 "degree_u is 1e+20, not a degree of 1 to 64");
  const auto file = write("g.txt", "");
  EXPECT_EQ(io_error_of([&] { (void)read_nurbs_patch(file); }),
            file.string() + ": unknown extension '.txt' (expected .igs, .iges, .json)");
  EXPECT_TRUE(is_nurbs_file("a.IGS"));
  EXPECT_FALSE(is_nurbs_file("a.xyz"));
}

}  // namespace
}  // namespace envcrust::io
