// Reader of plain-text point sets (.xyz/.pts/.txt/.csv): fields separated by white space or
// commas; either 3 or 6 numbers per line (position, optional normal), or any columns under a
// header line that names x, y, z (and optionally nx, ny, nz); .pts files may also hold
// Leica's point-count lines and x y z intensity [r g b] columns.
#include "io_detail.h"

#include "envcrust/io.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

namespace envcrust::io::detail {
namespace {

// Where a line's numbers are: the columns of x, y, z and of the normal, if any.
struct ColumnLayout {
  std::size_t fields = 0;  // fields per line
  std::array<std::size_t, 3> position{0, 1, 2};
  std::optional<std::array<std::size_t, 3>> normal;
  std::size_t line = 0;  // the line that set the layout
  bool from_header = false;
};

// A header's column name as compared: lower case, without quotes and a leading "//"
// (CloudCompare writes "//X,Y,Z,...").
std::string column_name(std::string_view field) {
  while (field.size() >= 2 && field.front() == '/' && field[1] == '/') field.remove_prefix(2);
  if (field.size() >= 2 && (field.front() == '"' || field.front() == '\'') && field.back() == field.front()) {
    field = field.substr(1, field.size() - 2);
  }
  std::string name(field);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name;
}

std::optional<std::size_t> find_column(const std::vector<std::string>& names,
                                       std::initializer_list<const char*> accepted) {
  for (std::size_t i = 0; i < names.size(); ++i)
    for (const char* a : accepted)
      if (names[i] == a) return i;
  return std::nullopt;
}

std::string joined(const std::vector<std::string_view>& fields) {
  std::string out;
  for (const auto& f : fields) out += (out.empty() ? "" : ", ") + quote(f);
  return out;
}

ColumnLayout header_layout(const std::filesystem::path& path, std::size_t line,
                           const std::vector<std::string_view>& fields) {
  std::vector<std::string> names;
  for (const auto& f : fields) names.push_back(column_name(f));
  ColumnLayout layout;
  layout.fields = fields.size();
  layout.line = line;
  layout.from_header = true;
  const auto x = find_column(names, {"x"});
  const auto y = find_column(names, {"y"});
  const auto z = find_column(names, {"z"});
  if (!x || !y || !z) {
    fail_at(path, line,
            "a header line must name the x, y and z columns (and may name nx, ny, nz), got " + joined(fields));
  }
  layout.position = {*x, *y, *z};
  const auto nx = find_column(names, {"nx", "normal_x", "normalx"});
  const auto ny = find_column(names, {"ny", "normal_y", "normaly"});
  const auto nz = find_column(names, {"nz", "normal_z", "normalz"});
  if (nx && ny && nz) {
    layout.normal = std::array<std::size_t, 3>{*nx, *ny, *nz};
  } else if (nx || ny || nz) {
    fail_at(path, line, "the header names some normal columns but not all three (nx, ny, nz), got " + joined(fields));
  }
  return layout;
}

// The layout of a headerless file, from its first line of numbers.
ColumnLayout numeric_layout(const std::filesystem::path& path, std::size_t line, std::size_t fields,
                            bool is_pts) {
  ColumnLayout layout;
  layout.fields = fields;
  layout.line = line;
  if (fields == 6) layout.normal = std::array<std::size_t, 3>{3, 4, 5};
  // Leica's .pts: x y z intensity, or x y z intensity r g b.
  const bool pts_columns = is_pts && (fields == 4 || fields == 7);
  if (fields != 3 && fields != 6 && !pts_columns) {
    fail_at(path, line,
            "expected 3 or 6 numbers (x y z, or x y z nx ny nz), got " + std::to_string(fields) +
                ": other columns (intensity, colour) are not read; keep the first 3 or 6, or name the "
                "columns in a header line (x y z ...)");
  }
  return layout;
}

bool is_count_line(const std::vector<std::string_view>& fields) {
  std::int64_t count = 0;
  return fields.size() == 1 && parse_int(fields.front(), count) && count >= 0;
}

// A header line has a field that is a name: not a number, and starting as names do (an
// empty field or "1.2.3" leaves the line a line of numbers, refused as one).
bool is_header(const std::vector<std::string_view>& fields) {
  double v = 0;
  return std::any_of(fields.begin(), fields.end(), [&](std::string_view f) {
    if (f.empty() || parse_double(f, v)) return false;
    const auto c = static_cast<unsigned char>(f.front());
    return std::isalpha(c) || c == '_' || c == '"' || c == '\'' || c == '/';
  });
}

}  // namespace

PointSet read_xyz(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  const bool is_pts = extension_of(path) == "pts";
  PointSet result;
  LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  std::optional<ColumnLayout> layout;
  while (lines.next(line)) {
    split_fields(strip_comment(line), tokens);
    if (tokens.empty()) {
      continue;
    }
    const std::size_t line_number = lines.line_number();
    // Leica's .pts starts each scan with its point count.
    if (is_pts && is_count_line(tokens)) {
      continue;
    }
    if (!layout) {
      layout = is_header(tokens) ? header_layout(path, line_number, tokens)
                                 : numeric_layout(path, line_number, tokens.size(), is_pts);
      if (layout->from_header) continue;
    } else if (tokens.size() != layout->fields) {
      const std::string expected = layout->from_header
                                       ? " fields (as the header on line " + std::to_string(layout->line) + " names)"
                                       : " numbers (as on line " + std::to_string(layout->line) + ")";
      fail_at(path, line_number,
              "expected " + std::to_string(layout->fields) + expected + ", got " + std::to_string(tokens.size()));
    }
    double v[6] = {};
    for (std::size_t i = 0; i < 6; ++i) {
      if (i >= 3 && !layout->normal) break;
      const std::size_t column = i < 3 ? layout->position[i] : (*layout->normal)[i - 3];
      if (!parse_double(tokens[column], v[i])) {
        fail_at(path, line_number, "expected a number, got " + quote(tokens[column]));
      }
      if (const char* problem = i < 3 ? coordinate_problem(v[i]) : std::isfinite(v[i]) ? nullptr : "non-finite normal") {
        fail_at(path, line_number, problem);
      }
    }
    result.points.emplace_back(v[0], v[1], v[2]);
    if (layout->normal) {
      result.normals.emplace_back(v[3], v[4], v[5]);
    }
  }
  if (result.points.empty()) {
    fail(path, "no points");
  }
  return result;
}

}  // namespace envcrust::io::detail
