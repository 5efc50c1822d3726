// Balls (the poles of `envcrust powercrust`): text "x y z radius [label]", one per line, or
// PLY vertices with `radius` and a `label` code.
#include "envcrust/io.h"

#include "io_detail.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace envcrust::io {

namespace {

// PLY label codes: 0 none/unknown, 1 in, 2 out (text labels other than these are refused).
constexpr const char* kLabelNames[] = {"unknown", "in", "out"};

std::uint8_t label_code(const std::filesystem::path& path, const std::string& label) {
  if (label.empty() || label == kLabelNames[0]) return 0;
  if (label == kLabelNames[1]) return 1;
  if (label == kLabelNames[2]) return 2;
  detail::fail(path, "cannot write ball label '" + label + "' to PLY (in, out or unknown)");
}

void check_radius(const std::filesystem::path& path, std::size_t line_or_index, double radius, bool is_line) {
  if (std::isfinite(radius) && radius > 0) return;
  std::ostringstream text;
  text << "radius must be finite and > 0 (got " << radius << ")";
  if (is_line) detail::fail_at(path, line_or_index, text.str());
  detail::fail(path, text.str() + " at ball " + std::to_string(line_or_index));
}

BallSet read_ply_balls(const std::filesystem::path& path) {
  const detail::RawMesh raw = detail::read_ply(path);
  if (raw.radii.empty() && !raw.vertices.empty()) detail::fail(path, "PLY vertices have no 'radius' property");
  BallSet balls;
  balls.centres = raw.vertices;
  balls.radii = raw.radii;
  for (std::size_t i = 0; i < raw.radii.size(); ++i) {
    check_radius(path, i, raw.radii[i], false);
    if (raw.labels.empty()) {
      balls.labels.emplace_back();
      continue;
    }
    const double code = raw.labels[i];
    if (code != 0 && code != 1 && code != 2)
      detail::fail(path, "ball " + std::to_string(i) + ": label code must be 0, 1 or 2");
    balls.labels.emplace_back(kLabelNames[static_cast<int>(code)]);
  }
  if (balls.centres.empty()) detail::fail(path, "no balls");
  return balls;
}

}  // namespace

void write_balls(const std::filesystem::path& path, const BallSet& balls) {
  const std::string extension = extension_of(path);
  if (balls.radii.size() != balls.centres.size() || balls.labels.size() != balls.centres.size())
    detail::fail(path, "cannot write balls: " + std::to_string(balls.centres.size()) + " centres, " +
                           std::to_string(balls.radii.size()) + " radii, " + std::to_string(balls.labels.size()) +
                           " labels");
  detail::check_finite(path, balls.centres, "ball centre");
  for (std::size_t i = 0; i < balls.radii.size(); ++i) check_radius(path, i, balls.radii[i], false);
  if (extension == "ply") {
    std::vector<std::uint8_t> codes;
    for (const auto& label : balls.labels) codes.push_back(label_code(path, label));
    write_atomic(path, true, [&](std::ostream& out) {
      out << "ply\nformat binary_little_endian 1.0\ncomment written by envcrust: balls, label 0 unknown 1 in 2 out\n"
          << "element vertex " << balls.centres.size() << "\n"
          << "property double x\nproperty double y\nproperty double z\nproperty double radius\n"
          << "property uchar label\nend_header\n";
      std::string buffer;
      for (std::size_t i = 0; i < balls.centres.size(); ++i) {
        const Point3& c = balls.centres[i];
        for (double v : {c.x(), c.y(), c.z(), balls.radii[i]}) detail::append_little_endian(buffer, v);
        buffer += static_cast<char>(codes[i]);
        detail::flush_buffer(out, buffer);
      }
      detail::flush_buffer(out, buffer, true);
    });
    return;
  }
  std::string text = "# x y z radius label\n";
  for (std::size_t i = 0; i < balls.centres.size(); ++i) {
    detail::append_point(text, balls.centres[i]);
    text += ' ';
    detail::append_double(text, balls.radii[i]);
    if (!balls.labels[i].empty()) text += ' ' + balls.labels[i];
    text += '\n';
  }
  write_text(path, text);
}

BallSet read_balls(const std::filesystem::path& path) {
  if (extension_of(path) == "ply") return read_ply_balls(path);
  const std::string data = detail::read_file(path);
  detail::LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  BallSet balls;
  while (lines.next(line)) {
    detail::split_tokens(detail::strip_comment(line), tokens);
    if (tokens.empty()) continue;
    const std::size_t number = lines.line_number();
    if (tokens.size() != 4 && tokens.size() != 5) {
      detail::fail_at(path, number, "expected x y z radius [label], got " +
                                        std::to_string(tokens.size()) + " values");
    }
    double values[4] = {};
    for (int k = 0; k < 4; ++k) {
      if (!detail::parse_double(tokens[k], values[k])) {
        detail::fail_at(path, number, "expected a number, got " + detail::quote(tokens[k]));
      }
    }
    for (int axis = 0; axis < 3; ++axis)
      if (const char* problem = detail::coordinate_problem(values[axis])) detail::fail_at(path, number, problem);
    check_radius(path, number, values[3], true);
    balls.centres.emplace_back(values[0], values[1], values[2]);
    balls.radii.push_back(values[3]);
    balls.labels.emplace_back(tokens.size() == 5 ? tokens[4] : std::string_view{});
  }
  if (balls.centres.empty()) detail::fail(path, "no balls");
  return balls;
}

}  // namespace envcrust::io
