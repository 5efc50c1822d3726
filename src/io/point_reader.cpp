// Reader of plain-text point sets (.xyz/.pts/.txt): 3 or 6 numbers per line, separated by
// white space or commas.
#include "io_detail.h"

#include <cmath>
#include <string>

namespace envcrust::io::detail {

PointSet read_xyz(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  PointSet result;
  LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  std::size_t columns = 0;
  std::size_t columns_line = 0;
  while (lines.next(line)) {
    split_fields(strip_comment(line), tokens);
    if (tokens.empty()) {
      continue;
    }
    const std::size_t line_number = lines.line_number();
    if (columns == 0) {
      if (tokens.size() != 3 && tokens.size() != 6) {
        fail_at(path, line_number,
                "expected 3 or 6 numbers (x y z, or x y z nx ny nz), got " + std::to_string(tokens.size()) +
                    ": other columns (intensity, colour) are not read; keep the first 3 or 6");
      }
      columns = tokens.size();
      columns_line = line_number;
    } else if (tokens.size() != columns) {
      fail_at(path, line_number,
              "expected " + std::to_string(columns) + " numbers (as on line " +
                  std::to_string(columns_line) + "), got " + std::to_string(tokens.size()));
    }
    double v[6] = {};
    for (std::size_t i = 0; i < columns; ++i) {
      if (!parse_double(tokens[i], v[i])) {
        fail_at(path, line_number, "expected a number, got " + quote(tokens[i]));
      }
      if (!std::isfinite(v[i])) {
        fail_at(path, line_number, i < 3 ? "non-finite coordinate" : "non-finite normal");
      }
    }
    result.points.emplace_back(v[0], v[1], v[2]);
    if (columns == 6) {
      result.normals.emplace_back(v[3], v[4], v[5]);
    }
  }
  if (result.points.empty()) {
    fail(path, "no points");
  }
  return result;
}

}  // namespace envcrust::io::detail
