// LAS input through `envcrust reconstruct` (issue 47 item 2): a coloured hemisphere comes out
// a disc with its colours, UTM-like coordinates give the shape found at the origin, --classes
// keeps some classes, and compressed or broken files are refused in one line.
#include "cli_fixture.h"
#include "fixtures/las_writer.h"

#include "envcrust/io.h"
#include "envcrust/nearest_index.h"
#include "envcrust/surfaces.h"

#include <algorithm>
#include <cmath>

namespace envcrust::testing {
namespace {

constexpr double kScale = 1e-4;  // the LAS files' scale: 0.1 mm on a unit hemisphere

// `count` samples of the built-in unit hemisphere (seed 1) at multiples of kScale, moved by
// `shift`, of class `classification`, coloured and given an intensity by their position.
std::vector<LasPoint> hemisphere(std::size_t count, const Vector3& shift = CGAL::NULL_VECTOR,
                                 std::uint8_t classification = 2) {
  surfaces::SampleOptions o;
  o.count = count;
  const PointSet samples = surfaces::sample_surface(*surfaces::make_builtin("hemisphere"), o);
  std::vector<LasPoint> points;
  for (const Point3& p : samples.points) {
    LasPoint q;
    const double c[3] = {p.x(), p.y(), p.z()};
    double* out[3] = {&q.x, &q.y, &q.z};
    for (int k = 0; k < 3; ++k) *out[k] = std::round(c[k] / kScale) * kScale + shift[k];
    auto channel = [](double t) { return static_cast<std::uint16_t>(std::lround(255 * std::clamp(t, 0.0, 1.0))); };
    q.rgb = {channel((p.x() + 1) / 2), channel((p.y() + 1) / 2), channel(p.z())};
    q.intensity = static_cast<std::uint16_t>(std::lround(1000 * p.z()));
    q.classification = classification;
    points.push_back(q);
  }
  return points;
}

LasLayout layout(unsigned minor, unsigned format, const Vector3& offset = CGAL::NULL_VECTOR) {
  LasLayout l;
  l.minor = minor;
  l.format = format;
  l.scale = {kScale, kScale, kScale};
  l.offset = {offset.x(), offset.y(), offset.z()};
  return l;
}

class Las : public CliTest {};

// The bar: a LAS 1.2 file of a hemisphere with RGB (point format 2) reconstructs as a
// disc, each vertex with the colour of its nearest input point.
TEST_F(Las, a_hemisphere_with_rgb_reconstructs_as_a_disc_with_its_colours_on_the_vertices) {
  write_las(path("h.las"), hemisphere(3000), layout(2, 2));
  const auto report = run_envcrust_json("reconstruct " + path("h.las") + " -o " + path("out.ply") + " --json");
  EXPECT_EQ(report["source"], "points");
  EXPECT_EQ(report["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(report["analysis"]["boundary_loops"], 1);
  EXPECT_EQ(report["analysis"]["components"], 1);
  EXPECT_EQ(report["output_vertex_data"]["colours"], true);
  EXPECT_EQ(report["output_vertex_data"]["scalars"], nlohmann::json({"intensity", "classification"}));
  EXPECT_FALSE(report.contains("input_origin"));
  const AttributedPoints input = io::read_attributed_points(path("h.las"));
  const AttributedPoints out = io::read_attributed_points(path("out.ply"));
  ASSERT_GT(out.points.size(), 1000U);
  ASSERT_EQ(out.attributes.colours.size(), out.points.size());
  // Each vertex's colour is that of an input point at its nearest distance (within the output's
  // float rounding).
  const NearestIndex index(input.points.points);
  std::size_t wrong = 0;
  for (std::size_t v = 0; v < out.points.size(); ++v) {
    const Point3& p = out.points.points[v];
    const double nearest = index.nearest(p).second;
    bool matches = false;
    for (std::size_t i = 0; i < input.points.size() && !matches; ++i)
      matches = std::sqrt(CGAL::squared_distance(p, input.points.points[i])) <= nearest + 1e-6 &&
                input.attributes.colours[i] == out.attributes.colours[v];
    if (!matches && wrong++ < 5) ADD_FAILURE() << "vertex " << v << " has not its nearest input point's colour";
  }
  EXPECT_EQ(wrong, 0U);
}

// The bar: LAS 1.4, point format 6, at coordinates near 500,000 / 5,000,000 gives the
// mesh of a copy at the origin, moved there, within 1e-6 of the diagonal.
TEST_F(Las, a_hemisphere_at_utm_coordinates_reconstructs_as_its_copy_at_the_origin) {
  const Vector3 utm(500000.0, 5000000.0, 0.0);
  write_las(path("near.las"), hemisphere(3000), layout(4, 6));
  write_las(path("far.las"), hemisphere(3000, utm), layout(4, 6, utm));
  const auto near = run_envcrust_json("reconstruct " + path("near.las") + " -o " + path("near.ply") + " --json");
  const auto far = run_envcrust_json("reconstruct " + path("far.las") + " -o " + path("far.ply") + " --json");
  EXPECT_EQ(far["input_origin"], nlohmann::json({500000.0, 5000000.0, 0.0}));
  for (const char* key : {"euler_characteristic", "boundary_loops", "vertices", "faces"})
    EXPECT_EQ(far["analysis"][key], near["analysis"][key]) << key;
  EXPECT_EQ(near["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(near["analysis"]["boundary_loops"], 1);
  const auto near_mesh = io::read_triangle_mesh(path("near.ply"));
  auto far_mesh = io::read_triangle_mesh(path("far.ply"));
  ASSERT_EQ(far_mesh.vertices.size(), near_mesh.vertices.size());
  // The far mesh lies where its input does (written in double there), and moved back it
  // matches the near one's vertices.
  double worst = 0;
  const NearestIndex index(near_mesh.vertices);
  for (const Point3& p : far_mesh.vertices) {
    EXPECT_GT(p.y(), 4999990.0);
    worst = std::max(worst, index.nearest(p - utm).second);
  }
  const double diagonal = std::sqrt(9.0);
  EXPECT_LT(worst, 1e-6 * diagonal) << "worst vertex distance " << worst;
}

// Ground (class 2) under a roof (class 6): --classes 2 reconstructs the ground alone.
TEST_F(Las, classes_keeps_only_the_points_of_those_classes) {
  auto points = hemisphere(2500);
  for (LasPoint p : hemisphere(400)) {
    p.z += 5;
    p.classification = 6;
    points.push_back(p);
  }
  write_las(path("t.las"), points, layout(2, 3));
  const auto report =
      run_envcrust_json("reconstruct " + path("t.las") + " --classes 2 -o " + path("out.ply") + " --json");
  EXPECT_EQ(report["notes"][0], "kept the 2500 of 2900 points of class 2");
  EXPECT_EQ(report["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(report["analysis"]["boundary_loops"], 1);
  EXPECT_EQ(report["analysis"]["components"], 1);
}

TEST_F(Las, classes_that_leave_no_point_are_refused_naming_the_classes_present) {
  auto points = hemisphere(300);
  points[0].classification = 6;
  write_las(path("t.las"), points, layout(4, 7));
  const CommandResult r = run_envcrust("reconstruct " + path("t.las") + " --classes 7,9 -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("t.las") +
                       ": no point is of class 7 or 9 (the points' classes: 2 (299 points), 6 (1 points))\n");
  EXPECT_FALSE(std::filesystem::exists(path("x.ply")));
  const CommandResult builtin = run_envcrust("reconstruct builtin:hemisphere --classes 2 -o " + path("x.ply"));
  EXPECT_EQ(builtin.exit_code, 2);
  EXPECT_EQ(builtin.err, "envcrust: usage error: --classes applies to point files: builtin:hemisphere has no classes\n");
}

TEST_F(Las, a_compressed_file_is_refused_naming_ways_to_decompress_it) {
  write_las(path("scan.laz"), hemisphere(100), layout(2, 2));
  expect_reconstruct_refuses("scan.laz", "compressed LAS (LAZ) is not read; decompress it first, e.g. with `laszip -i " +
                                             path("scan.laz") + " -o " + path("scan.las") + "` or `pdal translate " +
                                             path("scan.laz") + " " + path("scan.las") + "`");
}

TEST_F(Las, a_truncated_file_is_refused_in_one_line) {
  const std::string bytes = las_bytes(hemisphere(100), layout(4, 6));
  write_bytes(path("cut.las"), bytes.substr(0, bytes.size() - 40));
  expect_reconstruct_refuses("cut.las", "truncated point data: the header announces 100 points of 30 bytes, the file "
                                        "holds 98");
  write_bytes(path("short.las"), bytes.substr(0, 300));
  expect_reconstruct_refuses("short.las", "truncated header (300 bytes; a LAS 1.4 header has 375)");
}

}  // namespace
}  // namespace envcrust::testing
