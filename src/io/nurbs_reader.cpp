// Reading one NURBS patch: IGES rational B-spline surfaces (entity 128) and NURBS-Python's
// JSON exchange format.
#include "envcrust/io.h"

#include "io_detail.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace envcrust::io {

namespace {

using detail::fail;
using detail::fail_at;

constexpr int kIgesSurface = 128;       // rational B-spline surface
constexpr int kIgesTransform = 124;     // transformation matrix
constexpr int kIgesTrimmed = 144;       // trimmed (parametric) surface
constexpr int kIgesBounded = 143;       // bounded surface
constexpr std::size_t kIgesDataColumns = 72;
constexpr std::size_t kIgesParameterColumns = 64;

/// One directory entry: the fields an entity's parameters are found and placed with.
struct DirectoryEntry {
  int type = 0;
  std::size_t parameter_line = 0;  ///< first line of its parameters in the P section (from 1)
  std::size_t parameter_lines = 0;
  std::size_t transform = 0;       ///< directory line of a transformation matrix, 0 for none
  std::size_t line = 0;            ///< its own first line in the D section (the entity's pointer)
};

/// The lines of an IGES file by section letter (column 73), data columns only.
struct IgesSections {
  std::string global;                       ///< G lines' columns 1-72, joined
  std::vector<std::string> directory, parameters;
};

IgesSections split_sections(const std::filesystem::path& path, const std::string& text) {
  IgesSections s;
  detail::LineCursor cursor(text);
  std::string_view line;
  while (cursor.next(line)) {
    if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
    if (line.size() <= kIgesDataColumns)
      fail_at(path, cursor.line_number(), "not an IGES record (80 columns with the section letter in column 73)");
    const char section = line[kIgesDataColumns];
    const std::string data(line.substr(0, kIgesDataColumns));
    switch (section) {
      case 'S': case 'T': break;
      case 'G': s.global += data; break;
      case 'D': s.directory.push_back(data); break;
      case 'P': s.parameters.push_back(data); break;
      case 'C': fail(path, "compressed IGES is not supported (save it uncompressed)");
      default:
        fail_at(path, cursor.line_number(), std::string("unknown IGES section letter '") + section + "' in column 73");
    }
  }
  if (s.directory.empty()) fail(path, "not an IGES file (no directory entry section)");
  return s;
}

/// The parameter and record delimiters from the global section ("1H," and "1H;" by default).
std::pair<char, char> delimiters(const std::string& global) {
  char parameter = ',', record = ';';
  std::size_t pos = 0;
  if (global.compare(0, 2, "1H") == 0 && global.size() > 2) {
    parameter = global[2];
    pos = 4;  // past "1H" + delimiter + the delimiter that ends the field
  } else {
    pos = 1;  // an empty first field: the default, then a delimiter
  }
  if (global.compare(pos, 2, "1H") == 0 && global.size() > pos + 2) record = global[pos + 2];
  return {parameter, record};
}

std::size_t directory_field(const std::filesystem::path& path, const std::string& line, int field,
                            std::size_t line_number) {
  const std::string text = line.substr(static_cast<std::size_t>(field) * 8, 8);
  const auto first = text.find_first_not_of(' ');
  if (first == std::string::npos) return 0;
  std::int64_t value = 0;
  if (!detail::parse_int(std::string_view(text).substr(first, text.find_last_not_of(' ') - first + 1), value))
    fail(path, "directory line " + std::to_string(line_number) + ": field " + std::to_string(field + 1) +
                   " is not an integer ('" + text + "')");
  return static_cast<std::size_t>(std::abs(value));  // pointers may be negated (a negative means "a pointer")
}

std::vector<DirectoryEntry> read_directory(const std::filesystem::path& path, const IgesSections& s) {
  if (s.directory.size() % 2 != 0) fail(path, "the directory section has an odd number of lines (entries take two)");
  std::vector<DirectoryEntry> entries;
  for (std::size_t k = 0; k + 1 < s.directory.size(); k += 2) {
    DirectoryEntry e;
    e.line = k + 1;
    e.type = static_cast<int>(directory_field(path, s.directory[k], 0, e.line));
    e.parameter_line = directory_field(path, s.directory[k], 1, e.line);
    e.transform = directory_field(path, s.directory[k], 6, e.line);
    e.parameter_lines = directory_field(path, s.directory[k + 1], 3, e.line + 1);
    entries.push_back(e);
  }
  return entries;
}

/// An entity's parameters after its type number, as numbers (empty fields read as 0).
std::vector<double> entity_parameters(const std::filesystem::path& path, const IgesSections& s,
                                      const DirectoryEntry& e, std::pair<char, char> delimiter) {
  if (e.parameter_line == 0 || e.parameter_line + e.parameter_lines - 1 > s.parameters.size() || e.parameter_lines == 0)
    fail(path, "entity " + std::to_string(e.type) + " (directory line " + std::to_string(e.line) +
                   ") points to parameter lines " + std::to_string(e.parameter_line) + " to " +
                   std::to_string(e.parameter_line + e.parameter_lines - 1) + ", but the file has " +
                   std::to_string(s.parameters.size()));
  std::string text;
  for (std::size_t k = 0; k < e.parameter_lines; ++k)
    text += s.parameters[e.parameter_line - 1 + k].substr(0, kIgesParameterColumns);
  text = text.substr(0, text.find(delimiter.second));
  std::vector<double> values;
  std::size_t start = 0;
  bool is_first = true;
  for (;;) {
    const std::size_t end = std::min(text.find(delimiter.first, start), text.size());
    std::string field = text.substr(start, end - start);
    field.erase(std::remove(field.begin(), field.end(), ' '), field.end());
    std::replace_if(field.begin(), field.end(), [](char c) { return c == 'D' || c == 'd'; }, 'E');
    double value = 0;
    if (!field.empty() && !detail::parse_double(field, value))
      fail(path, "entity " + std::to_string(e.type) + " at parameter line " + std::to_string(e.parameter_line) +
                     ": '" + field + "' is not a number");
    if (!std::isfinite(value))
      fail(path, "entity " + std::to_string(e.type) + " at parameter line " + std::to_string(e.parameter_line) +
                     ": non-finite value '" + field + "'");
    if (!is_first) values.push_back(value);
    is_first = false;
    if (end >= text.size()) break;
    start = end + 1;
  }
  return values;
}

/// Apply the entity's transformation matrix (entity 124, chained) to the points.
void apply_transforms(const std::filesystem::path& path, const IgesSections& s,
                      const std::vector<DirectoryEntry>& entries, std::size_t transform,
                      std::pair<char, char> delimiter, std::vector<Point3>& points) {
  std::set<std::size_t> seen;
  while (transform != 0) {
    if (transform % 2 == 0 || (transform + 1) / 2 > entries.size() || !seen.insert(transform).second)
      fail(path, "transformation matrix pointer " + std::to_string(transform) + " does not name a directory entry");
    const DirectoryEntry& e = entries[(transform - 1) / 2];
    if (e.type != kIgesTransform)
      fail(path, "transformation matrix pointer " + std::to_string(transform) + " names entity " + std::to_string(e.type) + ", not 124");
    const auto m = entity_parameters(path, s, e, delimiter);
    if (m.size() < 12) fail(path, "transformation matrix (entity 124, directory line " + std::to_string(e.line) + ") has fewer than 12 values");
    for (auto& p : points)
      p = Point3(m[0] * p.x() + m[1] * p.y() + m[2] * p.z() + m[3], m[4] * p.x() + m[5] * p.y() + m[6] * p.z() + m[7],
                 m[8] * p.x() + m[9] * p.y() + m[10] * p.z() + m[11]);
    transform = e.transform;
  }
}

surfaces::NurbsPatch iges_surface(const std::filesystem::path& path, const IgesSections& s,
                                  const std::vector<DirectoryEntry>& entries, const DirectoryEntry& e,
                                  std::pair<char, char> delimiter) {
  const auto v = entity_parameters(path, s, e, delimiter);
  const std::string where = "rational B-spline surface (entity 128, directory line " + std::to_string(e.line) + ")";
  if (v.size() < 9) fail(path, where + ": fewer than 9 parameters");
  const auto as_count = [&](double x, const char* name) {
    if (x < 0 || x != std::floor(x) || x > 1e6) fail(path, where + ": " + name + " is not a valid count");
    return static_cast<std::size_t>(x);
  };
  const std::size_t k1 = as_count(v[0], "K1"), k2 = as_count(v[1], "K2");
  const std::size_t m1 = as_count(v[2], "M1 (degree in u)"), m2 = as_count(v[3], "M2 (degree in v)");
  surfaces::NurbsPatch p;
  p.degree_u = static_cast<int>(m1);
  p.degree_v = static_cast<int>(m2);
  p.count_u = k1 + 1;
  p.count_v = k2 + 1;
  const std::size_t knots_u = p.count_u + m1 + 1, knots_v = p.count_v + m2 + 1;
  const std::size_t net = p.count_u * p.count_v;
  const std::size_t needed = 9 + knots_u + knots_v + 4 * net + 4;
  if (v.size() < needed)
    fail(path, where + ": its parameters end early (" + std::to_string(v.size()) + " values, " +
                   std::to_string(needed) + " expected for " + std::to_string(p.count_u) + " x " +
                   std::to_string(p.count_v) + " control points of degree " + std::to_string(m1) + " x " +
                   std::to_string(m2) + ")");
  std::size_t at = 9;
  p.knots_u.assign(v.begin() + static_cast<std::ptrdiff_t>(at), v.begin() + static_cast<std::ptrdiff_t>(at + knots_u));
  at += knots_u;
  p.knots_v.assign(v.begin() + static_cast<std::ptrdiff_t>(at), v.begin() + static_cast<std::ptrdiff_t>(at + knots_v));
  at += knots_v;
  p.weights.assign(v.begin() + static_cast<std::ptrdiff_t>(at), v.begin() + static_cast<std::ptrdiff_t>(at + net));
  at += net;
  for (std::size_t k = 0; k < net; ++k, at += 3) p.control_points.emplace_back(v[at], v[at + 1], v[at + 2]);
  p.parameter_range = std::array<double, 4>{v[at], v[at + 1], v[at + 2], v[at + 3]};
  apply_transforms(path, s, entries, e.transform, delimiter, p.control_points);
  return p;
}

surfaces::NurbsPatch read_iges(const std::filesystem::path& path) {
  const IgesSections s = split_sections(path, detail::read_file(path));
  const auto delimiter = delimiters(s.global);
  const auto entries = read_directory(path, s);
  std::vector<const DirectoryEntry*> surfaces_found;
  std::map<int, std::size_t> types;
  for (const auto& e : entries) {
    ++types[e.type];
    if (e.type == kIgesTrimmed || e.type == kIgesBounded)
      fail(path, "a trimmed surface (IGES entity " + std::to_string(e.type) +
                     "): trimming curves are not supported; envcrust reads one untrimmed rational B-spline surface (entity 128)");
    if (e.type == kIgesSurface) surfaces_found.push_back(&e);
  }
  if (surfaces_found.empty()) {
    std::string list;
    for (const auto& [type, count] : types) list += (list.empty() ? "" : ", ") + std::to_string(type);
    fail(path, "no rational B-spline surface (IGES entity 128) in the file (its entities: " + list + ")");
  }
  if (surfaces_found.size() > 1)
    fail(path, std::to_string(surfaces_found.size()) +
                   " rational B-spline surfaces (IGES entity 128): envcrust reads one patch per file (sample them "
                   "into a point file or mesh them to reconstruct the whole)");
  return iges_surface(path, s, entries, *surfaces_found.front(), delimiter);
}

surfaces::NurbsPatch read_geomdl_json(const std::filesystem::path& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(detail::read_file(path));
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    const std::string what = e.what();
    const auto colon = what.find("parse error");
    fail(path, "invalid JSON: " + (colon == std::string::npos ? what : what.substr(colon)));
  }
  try {
    const auto& shape = j.at("shape");
    const std::string type = shape.at("type").get<std::string>();
    if (type != "surface") fail(path, "holds a NURBS " + type + ", not a surface (shape.type must be \"surface\")");
    const auto& data = shape.at("data");
    if (!data.is_array() || data.empty()) fail(path, "shape.data holds no surface");
    if (data.size() > 1)
      fail(path, std::to_string(data.size()) + " surfaces in shape.data: envcrust reads one patch per file");
    const auto& d = data.front();
    if (d.contains("trims") && !d.at("trims").at("data").empty())
      fail(path, "a trimmed surface: trimming curves are not supported; envcrust reads one untrimmed NURBS surface");
    surfaces::NurbsPatch p;
    p.degree_u = d.at("degree_u").get<int>();
    p.degree_v = d.at("degree_v").get<int>();
    p.count_u = d.at("size_u").get<std::size_t>();
    p.count_v = d.at("size_v").get<std::size_t>();
    p.knots_u = d.at("knotvector_u").get<std::vector<double>>();
    p.knots_v = d.at("knotvector_v").get<std::vector<double>>();
    const auto points = d.at("control_points").at("points").get<std::vector<std::vector<double>>>();
    if (points.size() != p.count_u * p.count_v)
      fail(path, std::to_string(points.size()) + " control points, size_u x size_v = " + std::to_string(p.count_u) +
                     " x " + std::to_string(p.count_v) + " expected");
    std::vector<double> weights(points.size(), 1.0);
    if (d.at("control_points").contains("weights"))
      weights = d.at("control_points").at("weights").get<std::vector<double>>();
    if (weights.size() != points.size())
      fail(path, std::to_string(weights.size()) + " weights for " + std::to_string(points.size()) + " control points");
    // NURBS-Python lists v fastest (index j + size_v * i); NurbsPatch wants u fastest.
    p.control_points.resize(points.size());
    p.weights.resize(points.size());
    for (std::size_t i = 0; i < p.count_u; ++i) {
      for (std::size_t jv = 0; jv < p.count_v; ++jv) {
        const auto& q = points[jv + p.count_v * i];
        if (q.size() != 3)
          fail(path, "control point " + std::to_string(jv + p.count_v * i) + " has " + std::to_string(q.size()) +
                         " coordinates, 3 expected");
        p.control_points[i + p.count_u * jv] = Point3(q[0], q[1], q[2]);
        p.weights[i + p.count_u * jv] = weights[jv + p.count_v * i];
      }
    }
    return p;
  } catch (const nlohmann::json::exception& e) {
    // out_of_range 403: "key 'degree_u' not found"; type_error 302: "type must be number, but is string"
    const std::string what = e.what();
    const auto bracket = what.find("] ");
    fail(path, "not a NURBS-Python surface: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  }
}

}  // namespace

bool is_nurbs_file(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  return extension == "igs" || extension == "iges" || extension == "json";
}

surfaces::NurbsPatch read_nurbs_patch(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  if (extension == "igs" || extension == "iges") return read_iges(path);
  if (extension == "json") return read_geomdl_json(path);
  detail::unknown_extension(path, ".igs, .iges, .json");
}

}  // namespace envcrust::io
