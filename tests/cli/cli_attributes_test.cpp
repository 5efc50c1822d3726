// Colours and scalar columns of a point file carried to the vertices `envcrust reconstruct`
// writes: each output vertex takes those of its nearest input point (issue 46 item 5).
#include "cli_fixture.h"

#include "envcrust/io.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <random>

namespace envcrust::testing {
namespace {

// A point of the input with the attributes the test gives it.
struct Sample {
  Point3 position;
  Colour colour{};
  float intensity = 0;
};

// n points of the upper unit hemisphere, uniform by area, at float-exact coordinates (so the
// files hold them exactly); colours and intensity vary smoothly with the position.
std::vector<Sample> hemisphere(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Sample> samples;
  while (samples.size() < n) {
    const double z = uniform(random);
    const double angle = 2 * M_PI * uniform(random);
    const double r = std::sqrt(1 - z * z);
    Sample s;
    s.position = Point3(static_cast<float>(r * std::cos(angle)), static_cast<float>(r * std::sin(angle)),
                        static_cast<float>(z));
    auto channel = [](double t) { return static_cast<std::uint8_t>(std::lround(255 * std::clamp(t, 0.0, 1.0))); };
    s.colour = {channel((s.position.x() + 1) / 2), channel((s.position.y() + 1) / 2), channel(s.position.z())};
    s.intensity = static_cast<float>(std::lround(1000 * s.position.x())) / 8;  // exact in text and float
    samples.push_back(s);
  }
  return samples;
}

std::string float_text(double v) {
  std::ostringstream s;
  s << std::setprecision(std::numeric_limits<float>::max_digits10) << static_cast<float>(v);
  return s.str();
}

std::string xyz_text(const Point3& p) { return float_text(p.x()) + " " + float_text(p.y()) + " " + float_text(p.z()); }

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// For each output vertex, the input samples nearest to it: those within a float's rounding
// (the output's positions are float32) of the nearest distance.
std::vector<std::vector<std::size_t>> nearest_samples(const std::vector<Sample>& samples,
                                                      const std::vector<Point3>& vertices) {
  std::vector<std::vector<std::size_t>> nearest;
  for (const Point3& v : vertices) {
    double best = std::numeric_limits<double>::infinity();
    for (const Sample& s : samples) best = std::min(best, std::sqrt(CGAL::squared_distance(v, s.position)));
    std::vector<std::size_t> within;
    for (std::size_t i = 0; i < samples.size(); ++i)
      if (std::sqrt(CGAL::squared_distance(v, samples[i].position)) <= best + 1e-6) within.push_back(i);
    nearest.push_back(std::move(within));
  }
  return nearest;
}

class Attributes : public CliTest {
 protected:
  // `envcrust reconstruct FILE -o out.ply`: exits 0, and returns the output read back, its
  // header and the report.
  AttributedPoints reconstruct(const std::string& file, std::string& header, nlohmann::json& report) {
    report = run_envcrust_json("reconstruct " + path(file) + " -o " + path("out.ply") + " --json");
    const std::string data = file_text(path("out.ply"));
    header = data.substr(0, data.find("end_header\n"));
    return io::read_attributed_points(path("out.ply"));
  }
};

// The bar: a PLY with RGB reconstructs to a PLY with RGB on its vertices, each the
// colour of the nearest input point, with float positions and normals.
TEST_F(Attributes, a_ply_with_colours_reconstructs_to_vertices_with_the_nearest_input_colour) {
  const auto samples = hemisphere(2000, 1);
  {
    std::ofstream out(path("h.ply"));
    out << "ply\nformat ascii 1.0\nelement vertex " << samples.size()
        << "\nproperty float x\nproperty float y\nproperty float z\n"
           "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (const Sample& s : samples)
      out << xyz_text(s.position) << " " << int{s.colour[0]} << " " << int{s.colour[1]} << " " << int{s.colour[2]} << "\n";
  }
  std::string header;
  nlohmann::json report;
  const AttributedPoints out = reconstruct("h.ply", header, report);
  for (const char* line : {"property float x\n", "property float y\n", "property float z\n", "property float nx\n",
                           "property float ny\n", "property float nz\n", "property uchar red\n",
                           "property uchar green\n", "property uchar blue\n"})
    EXPECT_NE(header.find(line), std::string::npos) << line << header;
  EXPECT_EQ(report["output_vertex_data"]["colours"], true) << report["output_vertex_data"];
  ASSERT_GT(out.points.size(), 500U);
  ASSERT_EQ(out.attributes.colours.size(), out.points.size());
  ASSERT_EQ(out.points.normals.size(), out.points.size());
  const auto nearest = nearest_samples(samples, out.points.points);
  std::size_t wrong = 0;
  for (std::size_t v = 0; v < nearest.size(); ++v) {
    const bool matches = std::any_of(nearest[v].begin(), nearest[v].end(),
                                     [&](std::size_t i) { return samples[i].colour == out.attributes.colours[v]; });
    if (!matches && wrong++ < 5) ADD_FAILURE() << "vertex " << v << " has not its nearest input point's colour";
  }
  EXPECT_EQ(wrong, 0U);
  // The normals are unit vectors, and away from the rim (where the border's faces may turn)
  // all face out of the hemisphere or all into it.
  std::size_t outward = 0, inner = 0;
  for (std::size_t v = 0; v < out.points.size(); ++v) {
    const Vector3 n = out.points.normals[v];
    EXPECT_NEAR(n.squared_length(), 1.0, 1e-5);
    if (out.points.points[v].z() < 0.1) continue;
    ++inner;
    outward += n * (out.points.points[v] - CGAL::ORIGIN) > 0 ? 1 : 0;
  }
  EXPECT_TRUE(outward == 0 || outward == inner) << outward << " of " << inner;
}

// `x y z intensity` files, refused before, reconstruct and the intensity reaches the output.
TEST_F(Attributes, a_four_column_file_carries_its_intensity_to_the_output) {
  const auto samples = hemisphere(2000, 2);
  {
    std::ofstream out(path("h.xyz"));
    for (const Sample& s : samples) out << xyz_text(s.position) << " " << s.intensity << "\n";
  }
  std::string header;
  nlohmann::json report;
  const AttributedPoints out = reconstruct("h.xyz", header, report);
  EXPECT_NE(header.find("property float intensity\n"), std::string::npos) << header;
  EXPECT_EQ(header.find("property uchar red\n"), std::string::npos) << header;
  ASSERT_EQ(out.attributes.names, std::vector<std::string>{"intensity"});
  const auto nearest = nearest_samples(samples, out.points.points);
  for (std::size_t v = 0; v < nearest.size(); ++v)
    EXPECT_TRUE(std::any_of(nearest[v].begin(), nearest[v].end(),
                            [&](std::size_t i) { return samples[i].intensity == out.attributes.scalars[0][v]; }))
        << "vertex " << v;
}

// Leica's .pts (a point count, then x y z intensity r g b): both reach the output.
TEST_F(Attributes, a_pts_file_carries_its_intensity_and_colours) {
  const auto samples = hemisphere(2000, 3);
  {
    std::ofstream out(path("h.pts"));
    out << samples.size() << "\n";
    for (const Sample& s : samples)
      out << xyz_text(s.position) << " " << s.intensity << " " << int{s.colour[0]} << " " << int{s.colour[1]} << " "
          << int{s.colour[2]} << "\n";
  }
  std::string header;
  nlohmann::json report;
  const AttributedPoints out = reconstruct("h.pts", header, report);
  ASSERT_EQ(out.attributes.names, std::vector<std::string>{"intensity"});
  ASSERT_EQ(out.attributes.colours.size(), out.points.size());
  const auto nearest = nearest_samples(samples, out.points.points);
  for (std::size_t v = 0; v < nearest.size(); ++v)
    EXPECT_TRUE(std::any_of(nearest[v].begin(), nearest[v].end(), [&](std::size_t i) {
      return samples[i].intensity == out.attributes.scalars[0][v] && samples[i].colour == out.attributes.colours[v];
    })) << "vertex " << v;
}

// A PLY property the reader has no role for is carried as a float property of its name, not
// refused and not dropped.
TEST_F(Attributes, an_unknown_ply_property_is_carried) {
  const auto samples = hemisphere(2000, 4);
  {
    std::ofstream out(path("h.ply"));
    out << "ply\nformat ascii 1.0\nelement vertex " << samples.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty float confidence\n"
           "property uchar scan_id\nend_header\n";
    for (std::size_t i = 0; i < samples.size(); ++i)
      out << xyz_text(samples[i].position) << " " << samples[i].intensity << " " << i % 3 << "\n";
  }
  std::string header;
  nlohmann::json report;
  const AttributedPoints out = reconstruct("h.ply", header, report);
  EXPECT_NE(header.find("property float confidence\n"), std::string::npos) << header;
  EXPECT_NE(header.find("property float scan_id\n"), std::string::npos) << header;
  EXPECT_EQ(report["output_vertex_data"]["scalars"], nlohmann::json({"confidence", "scan_id"}));
  ASSERT_EQ(out.attributes.names, (std::vector<std::string>{"confidence", "scan_id"}));
  const auto nearest = nearest_samples(samples, out.points.points);
  for (std::size_t v = 0; v < nearest.size(); ++v)
    EXPECT_TRUE(std::any_of(nearest[v].begin(), nearest[v].end(), [&](std::size_t i) {
      return samples[i].intensity == out.attributes.scalars[0][v] &&
             static_cast<float>(i % 3) == out.attributes.scalars[1][v];
    })) << "vertex " << v;
}

// A mesh's vertex colours (OBJ's "v x y z r g b") reach the output too: each output vertex
// takes the colour of the nearest vertex of the input mesh.
TEST_F(Attributes, a_mesh_with_vertex_colours_carries_them) {
  constexpr int kCells = 30;
  std::vector<Sample> vertices;
  {
    std::ofstream out(path("cap.obj"));
    for (int i = 0; i <= kCells; ++i) {
      for (int j = 0; j <= kCells; ++j) {
        const double x = -1 + 2.0 * i / kCells, y = -1 + 2.0 * j / kCells;
        Sample s;
        s.position = Point3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(0.3 * (x * x + y * y)));
        s.colour = {static_cast<std::uint8_t>(8 * i), static_cast<std::uint8_t>(8 * j), 200};
        out << "v " << xyz_text(s.position) << " " << int{s.colour[0]} << " " << int{s.colour[1]} << " 200\n";
        vertices.push_back(s);
      }
    }
    auto index = [](int i, int j) { return i * (kCells + 1) + j + 1; };
    for (int i = 0; i < kCells; ++i)
      for (int j = 0; j < kCells; ++j)
        out << "f " << index(i, j) << " " << index(i + 1, j) << " " << index(i + 1, j + 1) << " " << index(i, j + 1) << "\n";
  }
  std::string header;
  nlohmann::json report;
  const AttributedPoints out = reconstruct("cap.obj", header, report);
  EXPECT_NE(header.find("property uchar red\n"), std::string::npos) << header;
  ASSERT_EQ(out.attributes.colours.size(), out.points.size());
  const auto nearest = nearest_samples(vertices, out.points.points);
  for (std::size_t v = 0; v < nearest.size(); ++v)
    EXPECT_TRUE(std::any_of(nearest[v].begin(), nearest[v].end(),
                            [&](std::size_t i) { return vertices[i].colour == out.attributes.colours[v]; }))
        << "vertex " << v;
}

}  // namespace
}  // namespace envcrust::testing
