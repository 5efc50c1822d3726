// afsr_peer: CGAL's advancing-front surface reconstruction (Cohen-Steiner and Da, CGAL 5.5,
// Epick kernel, its default parameters) on a point file, for side-by-side measurement with
// `envcrust reconstruct` (scripts/realshape_table.py). A peer for measurement, not part of the
// product: no normals, no options beyond CGAL's two parameters.
//
//   afsr_peer POINTS -o OUT.(off|ply|obj|stl) [--radius-ratio-bound 5] [--beta 0.52]
//
// POINTS: .xyz/.pts/.txt (`x y z [nx ny nz]` per line; normals are ignored, `#` starts a
// comment) or .ply/.off (vertices, read with CGAL::IO::read_points). Prints one JSON line:
//   {"input":..., "points":N, "seconds_reconstruction":s, "seconds_total":s, "peak_mb":MB,
//    "vertices":V, "faces":F, "output":...}
// where vertices counts the input points the faces use (only those are written) and
// seconds_total includes reading and writing. Errors: one line `afsr_peer: error: FILE: ...`,
// exit 1 for bad input, 2 for usage, 3 for a failure inside CGAL.
#include "peak_memory.h"

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/IO/read_points.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Facet = std::array<std::size_t, 3>;

/// A problem with one named file: printed as `afsr_peer: error: FILE: what`.
struct FileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

/// `x y z [more columns]` per line; blank lines and `#` comments skipped.
std::vector<Point> read_xyz(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path + ": cannot open");
  std::vector<Point> points;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r,") == std::string::npos) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double x, y, z;
    if (!(fields >> x >> y >> z))
      throw FileError(path + ":" + std::to_string(number) + ": expected `x y z [nx ny nz]`");
    points.emplace_back(x, y, z);
  }
  return points;
}

std::vector<Point> read_input(const std::string& path) {
  const std::string ext = extension(path);
  if (ext == "xyz" || ext == "pts" || ext == "txt") return read_xyz(path);
  if (ext != "ply" && ext != "off")
    throw FileError(path + ": unknown extension (expected .xyz/.pts/.txt/.ply/.off)");
  if (!std::ifstream(path)) throw FileError(path + ": cannot open");
  std::vector<Point> points;
  // CGAL's readers print their own messages on std::cerr; the error here is the one line.
  std::ostringstream quiet;
  std::streambuf* cerr_buffer = std::cerr.rdbuf(quiet.rdbuf());
  const bool is_read = CGAL::IO::read_points(path, std::back_inserter(points));
  std::cerr.rdbuf(cerr_buffer);
  if (!is_read)
    throw FileError(path + ": cannot read its vertices as points");
  return points;
}

void check_points(const std::string& path, const std::vector<Point>& points) {
  if (points.size() < 4) throw FileError(path + ": " + std::to_string(points.size()) + " points, need at least 4");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw FileError(path + ": point " + std::to_string(i + 1) + " is not finite");
  }
  // AFSR needs a 3D Delaunay triangulation: refuse points that all lie in one plane.
  const Point& a = points[0];
  std::size_t b = 1;
  while (b < points.size() && points[b] == a) ++b;
  std::size_t c = b + 1;
  while (c < points.size() && (b == points.size() || CGAL::collinear(a, points[b], points[c]))) ++c;
  bool is_flat = b >= points.size() || c >= points.size();
  if (!is_flat) {
    is_flat = true;
    for (std::size_t d = c + 1; d < points.size() && is_flat; ++d)
      if (!CGAL::coplanar(a, points[b], points[c], points[d])) is_flat = false;
  }
  if (is_flat) throw FileError(path + ": all points lie in one plane (or line)");
}

void usage(const char* message) {
  std::fprintf(stderr,
               "afsr_peer: error: %s\nusage: afsr_peer POINTS -o OUT.(off|ply|obj|stl) "
               "[--radius-ratio-bound 5] [--beta 0.52]\n",
               message);
  std::exit(2);
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
  std::string input, output;
  double radius_ratio_bound = 5.0, beta = 0.52;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage((arg + " needs a value").c_str());
      return argv[++i];
    };
    auto number = [&]() {
      const std::string text = value();
      char* end = nullptr;
      const double x = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !std::isfinite(x) || x <= 0)
        usage((arg + ": expected a positive number, got '" + text + "'").c_str());
      return x;
    };
    if (arg == "-o" || arg == "--output") output = value();
    else if (arg == "--radius-ratio-bound") radius_ratio_bound = number();
    else if (arg == "--beta") beta = number();
    else if (arg == "-h" || arg == "--help") {
      std::printf("afsr_peer POINTS -o OUT.(off|ply|obj|stl) [--radius-ratio-bound 5] [--beta 0.52]\n");
      return 0;
    } else if (!arg.empty() && arg[0] == '-') usage(("unknown option " + arg).c_str());
    else if (input.empty()) input = arg;
    else usage(("more than one input: " + input + ", " + arg).c_str());
  }
  if (input.empty()) usage("no input file");
  if (output.empty()) usage("no output file (-o)");
  const std::string out_ext = extension(output);
  if (out_ext != "off" && out_ext != "ply" && out_ext != "obj" && out_ext != "stl")
    usage((output + ": unknown output extension (expected .off/.ply/.obj/.stl)").c_str());

  const auto t_total = std::chrono::steady_clock::now();
  std::vector<Point> points;
  try {
    points = read_input(input);
    check_points(input, points);
  } catch (const FileError& e) {
    std::fprintf(stderr, "afsr_peer: error: %s\n", e.what());
    return 1;
  }

  std::vector<Facet> facets;
  double seconds_reconstruction = 0;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(), std::back_inserter(facets),
                                                 radius_ratio_bound, beta);
    seconds_reconstruction = seconds_since(t0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "afsr_peer: error: %s: CGAL failed: %s\n", input.c_str(), e.what());
    return 3;
  }

  // Keep only the points the faces use, renumbered in input order.
  std::vector<std::size_t> index(points.size(), SIZE_MAX);
  for (const Facet& f : facets)
    for (std::size_t v : f) index[v] = 0;
  std::vector<Point> used;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (index[i] == 0) {
      index[i] = used.size();
      used.push_back(points[i]);
    }
  for (Facet& f : facets)
    for (std::size_t& v : f) v = index[v];

  // Written to OUT's name with `.tmp` before the extension (CGAL picks the format by it), then renamed.
  const std::string temp = output.substr(0, output.size() - out_ext.size()) + "tmp." + out_ext;
  if (!CGAL::IO::write_polygon_soup(temp, used, facets,
                                    CGAL::parameters::stream_precision(17).use_binary_mode(false)) ||
      std::rename(temp.c_str(), output.c_str()) != 0) {
    std::remove(temp.c_str());
    std::fprintf(stderr, "afsr_peer: error: %s: cannot write\n", output.c_str());
    return 1;
  }
  const double seconds_total = seconds_since(t_total);
  std::printf(
      "{\"input\": %s, \"points\": %zu, \"seconds_reconstruction\": %.3f, \"seconds_total\": %.3f, "
      "\"peak_mb\": %.1f, \"vertices\": %zu, \"faces\": %zu, \"output\": %s}\n",
      json_string(input).c_str(), points.size(), seconds_reconstruction, seconds_total,
      envcrust::bench::take_peak_mb(), used.size(), facets.size(), json_string(output).c_str());
  return 0;
}
