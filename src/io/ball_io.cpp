// Reading balls "x y z radius [label]", one per line (the poles of `envcrust powercrust`).
#include "envcrust/io.h"

#include "io_detail.h"

#include <cmath>
#include <sstream>

namespace envcrust::io {

BallSet read_balls(const std::filesystem::path& path) {
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
    if (!std::isfinite(values[0]) || !std::isfinite(values[1]) || !std::isfinite(values[2])) {
      detail::fail_at(path, number, "non-finite coordinate");
    }
    if (!(std::isfinite(values[3]) && values[3] > 0)) {
      std::ostringstream radius;
      radius << values[3];
      detail::fail_at(path, number, "radius must be finite and > 0 (got " + radius.str() + ")");
    }
    balls.centres.emplace_back(values[0], values[1], values[2]);
    balls.radii.push_back(values[3]);
    balls.labels.emplace_back(tokens.size() == 5 ? tokens[4] : std::string_view{});
  }
  if (balls.centres.empty()) detail::fail(path, "no balls");
  return balls;
}

}  // namespace envcrust::io
