// Reading and writing closed polylines: one point per line, or CGAL's "n x1 y1 z1 ... xn yn zn".
#include "envcrust/io.h"

#include "io_detail.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace envcrust::io {

namespace {

Point3 parse_point(const std::filesystem::path& path, std::size_t line,
                   const std::string_view* tokens) {
  double xyz[3] = {};
  for (int axis = 0; axis < 3; ++axis) {
    if (!detail::parse_double(tokens[axis], xyz[axis])) {
      detail::fail_at(path, line, "expected a number, got " + detail::quote(tokens[axis]));
    }
    if (const char* problem = detail::coordinate_problem(xyz[axis])) {
      detail::fail_at(path, line, problem);
    }
  }
  return {xyz[0], xyz[1], xyz[2]};
}

Polyline read_polyline_file(const std::filesystem::path& path) {
  const std::string data = detail::read_file(path);
  detail::LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  Polyline curve;
  bool cgal_format = false;
  std::size_t first_line = 0;
  while (lines.next(line)) {
    detail::split_fields(detail::strip_comment(line), tokens);
    if (tokens.empty()) {
      continue;
    }
    const std::size_t number = lines.line_number();
    if (cgal_format) {
      detail::fail_at(path, number,
                      "expected one polyline, found another after line " +
                          std::to_string(first_line));
    }
    if (first_line == 0) {
      first_line = number;
      std::int64_t count = 0;
      if (tokens.size() != 3 && detail::parse_int(tokens[0], count) && count >= 0 &&
          static_cast<std::uint64_t>(count) < tokens.size() &&
          tokens.size() == 1 + 3 * static_cast<std::uint64_t>(count)) {
        cgal_format = true;
        for (std::int64_t i = 0; i < count; ++i) {
          curve.push_back(parse_point(path, number, &tokens[1 + 3 * static_cast<std::size_t>(i)]));
        }
        continue;
      }
    }
    if (tokens.size() != 3) {
      detail::fail_at(path, number,
                      "expected 3 numbers, got " + std::to_string(tokens.size()) +
                          (number == first_line ? " (nor 'n x1 y1 z1 ... xn yn zn')" : ""));
    }
    curve.push_back(parse_point(path, number, tokens.data()));
  }
  return curve;
}

}  // namespace

Polyline read_polyline(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  Polyline curve;
  if (extension == "polyline") {
    curve = read_polyline_file(path);
  } else if (is_text_point_file(path)) {
    curve = detail::read_xyz(path).points.points;
  } else {
    detail::unknown_extension(path, ".polyline, .xyz, .txt, .pts, .csv");
  }
  // A point repeated in a row is one vertex (a zero-length edge says nothing), and closed
  // curves are stored without repeating their first point.
  const std::size_t read = curve.size();
  curve.erase(std::unique(curve.begin(), curve.end()), curve.end());
  const bool had_repeats = curve.size() < read;
  if (curve.size() > 1 && curve.back() == curve.front()) {
    curve.pop_back();
  }
  if (curve.size() < 3) {
    detail::fail(path, "polyline has " + std::to_string(curve.size()) +
                           (had_repeats ? " distinct" : "") + " points (need at least 3)");
  }
  return curve;
}

void write_polyline(const std::filesystem::path& path, const Polyline& curve) {
  const std::string extension = extension_of(path);
  if (extension != "polyline" && extension != "xyz") {
    detail::unknown_extension(path, ".polyline, .xyz");
  }
  detail::check_finite(path, curve, "point");
  write_atomic(path, false, [&](std::ostream& out) {
    std::string buffer;
    for (const Point3& p : curve) {
      detail::append_point(buffer, p);
      buffer += '\n';
      detail::flush_buffer(out, buffer);
    }
    detail::flush_buffer(out, buffer, true);
  });
}

}  // namespace envcrust::io
