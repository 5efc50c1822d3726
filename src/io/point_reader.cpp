// Reader of plain-text point sets (.xyz/.pts/.txt/.csv): fields separated by white space or
// commas; x y z first and any columns after them (normals, colours, intensity, ...), or any
// columns under a header line that names x, y, z; .pts files may also hold Leica's
// point-count lines. Columns that are neither position nor normal are kept as attributes:
// a scan's colours and intensity are carried to the output, not refused.
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

// Where a line's numbers are: the columns of x, y, z and of the normal, if any; every other
// column is an attribute.
struct ColumnLayout {
  std::size_t fields = 0;  // fields per line
  std::array<std::size_t, 3> position{0, 1, 2};
  std::optional<std::array<std::size_t, 3>> normal;
  std::optional<std::array<std::size_t, 3>> colour;  // named red, green, blue by a header
  std::vector<std::string> names;                    // the header's names, one per field
  std::size_t line = 0;  // the line that set the layout
  bool from_header = false;
};

// The values of the columns that are neither position nor normal, one vector per field (empty
// for the others), and whether every value of the column was a number.
struct ExtraColumns {
  std::vector<std::vector<double>> values;
  std::vector<char> numeric;
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
  const auto r = find_column(names, {"r", "red"});
  const auto g = find_column(names, {"g", "green"});
  const auto b = find_column(names, {"b", "blue"});
  if (r && g && b) layout.colour = std::array<std::size_t, 3>{*r, *g, *b};
  layout.names = std::move(names);
  return layout;
}

// The layout of a headerless file, from its first line of numbers: x y z, and x y z nx ny nz
// for 6 columns (as every exporter writes normals); the other columns' roles are chosen once
// all lines are read (headerless_attributes).
ColumnLayout numeric_layout(const std::filesystem::path& path, std::size_t line, std::size_t fields) {
  ColumnLayout layout;
  layout.fields = fields;
  layout.line = line;
  if (fields == 6) layout.normal = std::array<std::size_t, 3>{3, 4, 5};
  if (fields < 3) {
    fail_at(path, line,
            "expected at least 3 numbers (x y z, then optional columns: nx ny nz, intensity, r g b, ...), got " +
                std::to_string(fields));
  }
  return layout;
}

// Three columns of whole numbers in 0..255, some above 1: colours (read as normals they would
// all point into one octant).
bool look_like_colours(const ExtraColumns& extra, std::size_t first) {
  bool above_one = false;
  for (std::size_t c = first; c < first + 3; ++c) {
    for (const double v : extra.values[c]) {
      if (!(v >= 0 && v <= 255 && v == std::floor(v))) return false;
      above_one = above_one || v > 1;
    }
  }
  return above_one;
}

// Colour columns as 0..255: values all within 0..1 and not all whole are fractions of 1
// (as some exporters write them); else they are 0..255, rounded and clamped.
void add_colours(const ExtraColumns& extra, const std::array<std::size_t, 3>& columns, PointAttributes& out) {
  bool fractions = true, some_fraction = false;
  for (const std::size_t c : columns) {
    for (const double v : extra.values[c]) {
      fractions = fractions && v >= 0 && v <= 1;
      some_fraction = some_fraction || v != std::floor(v);
    }
  }
  const double scale = fractions && some_fraction ? 255.0 : 1.0;
  const std::size_t n = extra.values[columns[0]].size();
  out.colours.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const double v = extra.values[columns[k]][i] * scale;
      out.colours[i][k] = v > 0 ? static_cast<std::uint8_t>(std::lround(std::min(v, 255.0))) : 0;
    }
  }
}

void add_scalar(const ExtraColumns& extra, std::size_t column, std::string name, PointAttributes& out) {
  if (name.empty()) name = "column_" + std::to_string(column + 1);
  out.names.push_back(std::move(name));
  out.scalars.emplace_back(extra.values[column].begin(), extra.values[column].end());
}

// A headerless file's columns after x y z: 4 columns x y z intensity (a scanner's export);
// 6 x y z nx ny nz (set by numeric_layout); 7 x y z intensity r g b (Leica's .pts); 9 normals
// and colours, the triple of whole numbers 0..255 taken as the colour (CloudCompare writes
// x y z r g b nx ny nz, others x y z nx ny nz r g b); any other count scalars column_N.
void headerless_attributes(const std::filesystem::path& path, const ExtraColumns& extra, std::size_t fields,
                           PointSet& points, PointAttributes& out) {
  std::vector<char> taken(fields, 0);
  taken[0] = taken[1] = taken[2] = 1;
  if (fields == 4 || fields == 7) {
    add_scalar(extra, 3, "intensity", out);
    taken[3] = 1;
  }
  if (fields == 7 && look_like_colours(extra, 4)) {
    add_colours(extra, {4, 5, 6}, out);
    taken[4] = taken[5] = taken[6] = 1;
  }
  if (fields == 9) {
    const bool colours_first = look_like_colours(extra, 3) && !look_like_colours(extra, 6);
    const std::size_t normal = colours_first ? 6 : 3;
    for (std::size_t i = 0; i < extra.values[normal].size(); ++i) {
      const Vector3 n(extra.values[normal][i], extra.values[normal + 1][i], extra.values[normal + 2][i]);
      if (!std::isfinite(n.x()) || !std::isfinite(n.y()) || !std::isfinite(n.z()))
        fail(path, "point " + std::to_string(i + 1) + ": non-finite normal");
      points.normals.push_back(n);
    }
    for (std::size_t c = normal; c < normal + 3; ++c) taken[c] = 1;
    if (colours_first || look_like_colours(extra, 6)) {
      const std::size_t colour = colours_first ? 3 : 6;
      add_colours(extra, {colour, colour + 1, colour + 2}, out);
      for (std::size_t c = colour; c < colour + 3; ++c) taken[c] = 1;
    }
  }
  for (std::size_t c = 3; c < fields; ++c)
    if (!taken[c] && !extra.values[c].empty()) add_scalar(extra, c, "", out);
}

// A header's columns after x y z and the normal: the named colour, and every other column
// whose values are all numbers, a scalar of its name (a column of text, such as a class
// name, is dropped).
void header_attributes(const ColumnLayout& layout, const ExtraColumns& extra, PointAttributes& out) {
  std::vector<char> taken(layout.fields, 0);
  if (layout.colour && extra.numeric[(*layout.colour)[0]] && extra.numeric[(*layout.colour)[1]] &&
      extra.numeric[(*layout.colour)[2]]) {
    add_colours(extra, *layout.colour, out);
    for (const std::size_t c : *layout.colour) taken[c] = 1;
  }
  for (std::size_t c = 0; c < layout.fields; ++c)
    if (!taken[c] && extra.numeric[c] && !extra.values[c].empty()) add_scalar(extra, c, layout.names[c], out);
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

AttributedPoints read_xyz(const std::filesystem::path& path) {
  const std::string data = read_file(path);
  const bool is_pts = extension_of(path) == "pts";
  AttributedPoints result;
  PointSet& points = result.points;
  LineCursor lines(data);
  std::string_view line;
  std::vector<std::string_view> tokens;
  std::optional<ColumnLayout> layout;
  ExtraColumns extra;
  std::vector<char> is_role;  // per field: position or normal, read into `points`
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
                                 : numeric_layout(path, line_number, tokens.size());
      is_role.assign(layout->fields, 0);
      for (const std::size_t c : layout->position) is_role[c] = 1;
      if (layout->normal)
        for (const std::size_t c : *layout->normal) is_role[c] = 1;
      extra.values.resize(layout->fields);
      extra.numeric.assign(layout->fields, 1);
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
    points.points.emplace_back(v[0], v[1], v[2]);
    if (layout->normal) {
      points.normals.emplace_back(v[3], v[4], v[5]);
    }
    // The other columns: numbers in a headerless file and in a header's colour columns; a
    // header's other columns may hold text (then they are no attribute).
    for (std::size_t c = 0; c < layout->fields; ++c) {
      if (is_role[c] || !extra.numeric[c]) continue;
      double value = 0;
      if (parse_double(tokens[c], value)) {
        extra.values[c].push_back(value);
        continue;
      }
      const bool is_colour = layout->colour && std::find(layout->colour->begin(), layout->colour->end(), c) !=
                                                   layout->colour->end();
      if (!layout->from_header || is_colour) fail_at(path, line_number, "expected a number, got " + quote(tokens[c]));
      extra.numeric[c] = 0;
      extra.values[c].clear();
      extra.values[c].shrink_to_fit();
    }
  }
  if (points.points.empty()) {
    fail(path, "no points");
  }
  if (layout->from_header) {
    header_attributes(*layout, extra, result.attributes);
  } else {
    headerless_attributes(path, extra, layout->fields, points, result.attributes);
  }
  return result;
}

}  // namespace envcrust::io::detail
