// Reading one NURBS patch from an IGES file: a rational B-spline surface (entity 128), alone
// or under a trimmed surface (entity 144) with its trimming loops, placed by its
// transformation matrices (entity 124).
#include "io_detail.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

namespace envcrust::io::detail {

namespace {

constexpr int kSurface = 128;        // rational B-spline surface
constexpr int kTransform = 124;      // transformation matrix
constexpr int kTrimmed = 144;        // trimmed (parametric) surface
constexpr int kBounded = 143;        // bounded surface
constexpr int kCurveOnSurface = 142;
constexpr int kComposite = 102;      // composite curve
constexpr int kLine = 110;
constexpr int kSplineCurve = 126;    // rational B-spline curve
constexpr int kArc = 100;            // circular arc
constexpr std::size_t kDataColumns = 72;
constexpr std::size_t kParameterColumns = 64;
/// A parameter-plane point within this fraction of the domain's size lies on its border.
constexpr double kBorderTolerance = 1e-6;
constexpr double kMaxPointer = 1e9;  // directory pointers: 8 digits

/// One directory entry: where an entity's parameters are and how it is placed.
struct DirectoryEntry {
  int type = 0;
  std::size_t parameter_line = 0;  ///< first line of its parameters in the P section (from 1)
  std::size_t parameter_lines = 0;
  std::size_t transform = 0;       ///< directory line of a transformation matrix, 0 for none
  std::size_t line = 0;            ///< its own first line in the D section (its pointer)
};

std::string describe(const DirectoryEntry& e) {
  return "entity " + std::to_string(e.type) + " (directory line " + std::to_string(e.line) + ")";
}

/// The file's sections, directory and delimiters, and the entities' parameters on demand.
class IgesFile {
 public:
  explicit IgesFile(std::filesystem::path path) : path_(std::move(path)) {
    split_sections(read_file(path_));
    read_delimiters();
    read_directory();
  }

  [[nodiscard]] const std::vector<DirectoryEntry>& entries() const { return entries_; }
  [[noreturn]] void fail(const std::string& problem) const { detail::fail(path_, problem); }

  /// The entry a directory pointer names. @throws IoError if it names none.
  [[nodiscard]] const DirectoryEntry& entry(std::size_t pointer, const std::string& what) const {
    if (pointer == 0 || pointer % 2 == 0 || (pointer + 1) / 2 > entries_.size())
      fail(what + " pointer " + std::to_string(pointer) + " does not name a directory entry");
    return entries_[(pointer - 1) / 2];
  }

  /// An entity's parameters after its type number, as numbers (empty fields read as 0).
  [[nodiscard]] std::vector<double> parameters(const DirectoryEntry& e) const {
    if (e.parameter_line == 0 || e.parameter_lines == 0 ||
        e.parameter_line + e.parameter_lines - 1 > parameter_lines_.size())
      fail(describe(e) + " points to parameter lines " + std::to_string(e.parameter_line) + " to " +
           std::to_string(e.parameter_line + e.parameter_lines - 1) + ", but the file has " +
           std::to_string(parameter_lines_.size()));
    std::string text;
    for (std::size_t k = 0; k < e.parameter_lines; ++k)
      text += parameter_lines_[e.parameter_line - 1 + k].substr(0, kParameterColumns);
    text = text.substr(0, text.find(record_delimiter_));
    std::vector<double> values;
    std::size_t start = 0;
    for (bool is_first = true;; is_first = false) {
      const std::size_t end = std::min(text.find(parameter_delimiter_, start), text.size());
      std::string field = text.substr(start, end - start);
      field.erase(std::remove(field.begin(), field.end(), ' '), field.end());
      std::replace_if(field.begin(), field.end(), [](char c) { return c == 'D' || c == 'd'; }, 'E');
      double value = 0;
      const std::string where = "entity " + std::to_string(e.type) + " at parameter line " + std::to_string(e.parameter_line);
      if (!field.empty() && !parse_double(field, value)) fail(where + ": '" + field + "' is not a number");
      if (!std::isfinite(value)) fail(where + ": non-finite value '" + field + "'");
      if (!is_first) values.push_back(value);
      if (end >= text.size()) break;
      start = end + 1;
    }
    return values;
  }

  /// Apply the transformation matrices (entity 124, chained) starting at `transform`.
  void apply_transforms(std::size_t transform, std::vector<Point3>& points) const {
    std::set<std::size_t> seen;
    while (transform != 0) {
      const DirectoryEntry& e = entry(transform, "transformation matrix");
      if (e.type != kTransform || !seen.insert(transform).second)
        fail("transformation matrix pointer " + std::to_string(transform) + " names " + describe(e) +
             (e.type == kTransform ? " twice (a loop)" : ", not 124"));
      const auto m = parameters(e);
      if (m.size() < 12) fail("transformation matrix (" + describe(e) + ") has fewer than 12 values");
      for (auto& p : points)
        p = Point3(m[0] * p.x() + m[1] * p.y() + m[2] * p.z() + m[3], m[4] * p.x() + m[5] * p.y() + m[6] * p.z() + m[7],
                   m[8] * p.x() + m[9] * p.y() + m[10] * p.z() + m[11]);
      transform = e.transform;
    }
  }

 private:
  void split_sections(const std::string& text) {
    LineCursor cursor(text);
    std::string_view line;
    while (cursor.next(line)) {
      if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
      if (line.size() <= kDataColumns)
        fail_at(path_, cursor.line_number(), "not an IGES record (80 columns with the section letter in column 73)");
      const char section = line[kDataColumns];
      const std::string data(line.substr(0, kDataColumns));
      switch (section) {
        case 'S': case 'T': break;
        case 'G': global_ += data; break;
        case 'D': directory_lines_.push_back(data); break;
        case 'P': parameter_lines_.push_back(data); break;
        case 'C': fail("compressed IGES is not supported (save it uncompressed)");
        default:
          fail_at(path_, cursor.line_number(), std::string("unknown IGES section letter '") + section + "' in column 73");
      }
    }
    if (directory_lines_.empty()) fail("not an IGES file (no directory entry section)");
  }

  /// The parameter and record delimiters, the global section's first two fields ("1H," and
  /// "1H;"; an empty field keeps the default).
  void read_delimiters() {
    // A "1Hc" field at pos (a missing or short global section keeps the defaults).
    auto hollerith_at = [&](std::size_t pos) { return global_.size() > pos + 2 && global_.compare(pos, 2, "1H") == 0; };
    std::size_t pos = 1;  // an empty first field: the default, then a delimiter
    if (hollerith_at(0)) {
      parameter_delimiter_ = global_[2];
      pos = 4;  // past "1H" + the delimiter + the delimiter that ends the field
    }
    if (hollerith_at(pos)) record_delimiter_ = global_[pos + 2];
  }

  [[nodiscard]] std::size_t directory_field(std::size_t line, int field) const {
    const std::string text = directory_lines_[line].substr(static_cast<std::size_t>(field) * 8, 8);
    const auto first = text.find_first_not_of(' ');
    if (first == std::string::npos) return 0;
    std::int64_t value = 0;
    if (!parse_int(std::string_view(text).substr(first, text.find_last_not_of(' ') - first + 1), value))
      fail("directory line " + std::to_string(line + 1) + ": field " + std::to_string(field + 1) +
           " is not an integer ('" + text + "')");
    return static_cast<std::size_t>(std::abs(value));  // a negative value marks a pointer
  }

  void read_directory() {
    if (directory_lines_.size() % 2 != 0) fail("the directory section has an odd number of lines (entries take two)");
    for (std::size_t k = 0; k + 1 < directory_lines_.size(); k += 2) {
      DirectoryEntry e;
      e.line = k + 1;
      e.type = static_cast<int>(directory_field(k, 0));
      e.parameter_line = directory_field(k, 1);
      e.transform = directory_field(k, 6);
      e.parameter_lines = directory_field(k + 1, 3);
      entries_.push_back(e);
    }
  }

  std::filesystem::path path_;
  std::string global_;
  std::vector<std::string> directory_lines_, parameter_lines_;
  std::vector<DirectoryEntry> entries_;
  char parameter_delimiter_ = ',', record_delimiter_ = ';';
};

// A count or a pointer, stored as a number: a whole number in [0, limit] (casting a value
// beyond the integers' range, such as 1e300, would be undefined).
std::size_t whole_number(const IgesFile& file, double x, double limit, const std::string& what) {
  if (!(x >= 0 && x <= limit && x == std::floor(x))) {
    std::ostringstream text;
    text << what << " is " << x << ", not a whole number from 0 to " << limit;
    file.fail(text.str());
  }
  return static_cast<std::size_t>(x);
}

surfaces::NurbsPatch read_surface(const IgesFile& file, const DirectoryEntry& e) {
  const auto v = file.parameters(e);
  const std::string where = "rational B-spline surface (entity 128, directory line " + std::to_string(e.line) + ")";
  if (v.size() < 9) file.fail(where + ": fewer than 9 parameters");
  const auto as_count = [&](double x, const char* name) {
    if (x < 0 || x != std::floor(x) || x > 1e6) file.fail(where + ": " + name + " is not a valid count");
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
    file.fail(where + ": its parameters end early (" + std::to_string(v.size()) + " values, " + std::to_string(needed) +
              " expected for " + std::to_string(p.count_u) + " x " + std::to_string(p.count_v) +
              " control points of degree " + std::to_string(m1) + " x " + std::to_string(m2) + ")");
  const auto take = [&](std::size_t& at, std::size_t count) {
    std::vector<double> out(v.begin() + static_cast<std::ptrdiff_t>(at), v.begin() + static_cast<std::ptrdiff_t>(at + count));
    at += count;
    return out;
  };
  std::size_t at = 9;
  p.knots_u = take(at, knots_u);
  p.knots_v = take(at, knots_v);
  p.weights = take(at, net);
  for (std::size_t k = 0; k < net; ++k, at += 3) p.control_points.emplace_back(v[at], v[at + 1], v[at + 2]);
  p.parameter_range = std::array<double, 4>{v[at], v[at + 1], v[at + 2], v[at + 3]};
  file.apply_transforms(e.transform, p.control_points);
  return p;
}

/// A polyline of the parameter plane as a degree-1 trimming curve.
surfaces::TrimCurve polyline_curve(std::vector<std::array<double, 2>> points) {
  surfaces::TrimCurve c;
  c.degree = 1;
  c.knots.push_back(0);
  for (std::size_t k = 0; k < points.size(); ++k) c.knots.push_back(static_cast<double>(k));
  c.knots.push_back(static_cast<double>(points.size() - 1));
  c.weights.assign(points.size(), 1.0);
  c.points = std::move(points);
  return c;
}

/// Points per full turn of a circular arc (entity 100) turned into a polyline.
constexpr int kArcPointsPerTurn = 1024;

/// The parameter-plane curves of a trimming curve, in order: a line (110), a circular arc
/// (100, as a fine polyline), a B-spline curve (126), the pieces of a composite curve (102).
void collect_curves(const IgesFile& file, std::size_t pointer, std::vector<surfaces::TrimCurve>& curves, int depth = 0) {
  const DirectoryEntry& e = file.entry(pointer, "trimming curve");
  if (e.transform != 0 && e.type != kComposite)
    file.fail("a trimming curve (" + describe(e) + ") placed by a transformation matrix: not supported");
  const auto v = file.parameters(e);
  const auto short_of = [&](std::size_t count) {
    if (v.size() < count) file.fail(describe(e) + ": fewer than " + std::to_string(count) + " parameters");
  };
  if (e.type == kLine) {
    short_of(6);
    curves.push_back(polyline_curve({{v[0], v[1]}, {v[3], v[4]}}));
  } else if (e.type == kArc) {
    short_of(7);  // ZT, centre, start, end; counterclockwise from start to end
    const double cu = v[1], cv = v[2];
    const double radius = std::hypot(v[3] - cu, v[4] - cv);
    const double a0 = std::atan2(v[4] - cv, v[3] - cu);
    double a1 = std::atan2(v[6] - cv, v[5] - cu);
    if (a1 <= a0 + 1e-12) a1 += 2 * std::numbers::pi;
    const int steps = std::max(8, static_cast<int>(std::ceil(kArcPointsPerTurn * (a1 - a0) / (2 * std::numbers::pi))));
    std::vector<std::array<double, 2>> points;
    for (int k = 0; k <= steps; ++k) {
      const double a = a0 + (a1 - a0) * k / steps;
      points.push_back({cu + radius * std::cos(a), cv + radius * std::sin(a)});
    }
    curves.push_back(polyline_curve(std::move(points)));
  } else if (e.type == kSplineCurve) {
    short_of(6);
    if (v[0] < 0 || v[1] < 1 || v[0] > 1e6 || v[1] > 64) file.fail(describe(e) + ": K or M out of range");
    const auto k = static_cast<std::size_t>(v[0]), m = static_cast<std::size_t>(v[1]);
    const std::size_t first_weight = 6 + (k + m + 2), first_point = first_weight + (k + 1);
    short_of(first_point + 3 * (k + 1));
    surfaces::TrimCurve c;
    c.degree = static_cast<int>(m);
    c.knots.assign(v.begin() + 6, v.begin() + static_cast<std::ptrdiff_t>(first_weight));
    c.weights.assign(v.begin() + static_cast<std::ptrdiff_t>(first_weight), v.begin() + static_cast<std::ptrdiff_t>(first_point));
    for (std::size_t i = 0; i <= k; ++i) c.points.push_back({v[first_point + 3 * i], v[first_point + 3 * i + 1]});
    curves.push_back(std::move(c));
  } else if (e.type == kComposite && depth < 8) {
    short_of(1);
    const std::size_t n = whole_number(file, v[0], 1e6, describe(e) + ": its curve count");
    short_of(1 + n);
    for (std::size_t i = 0; i < n; ++i)
      collect_curves(file, whole_number(file, v[1 + i], kMaxPointer, describe(e) + ": a curve pointer"), curves, depth + 1);
  } else {
    file.fail("a trimming curve of IGES entity " + std::to_string(e.type) +
              " (lines 110, circular arcs 100, B-spline curves 126 and composite curves 102 are read)");
  }
}

/// Whether a trimming loop runs along the whole border of the domain [u0,u1] x [v0,v1]: every
/// curve's control points lie on one side of it (so the curve does), and the curves together
/// are as long as its perimeter.
bool is_domain_border(const std::vector<surfaces::TrimCurve>& curves, const std::array<double, 4>& r) {
  const double du = r[1] - r[0], dv = r[3] - r[2];
  const double tol = kBorderTolerance * std::max(du, dv);
  double covered = 0;
  for (const auto& curve : curves) {
    bool on_side = false;
    for (int side = 0; side < 4 && !on_side; ++side) {
      const auto coordinate = static_cast<std::size_t>(side < 2 ? 0 : 1);  // sides u = u0, u = u1, v = v0, v = v1
      const double value = r[static_cast<std::size_t>(side)];
      on_side = std::all_of(curve.points.begin(), curve.points.end(),
                            [&](const auto& p) { return std::abs(p[coordinate] - value) <= tol; });
      if (on_side) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const auto& p : curve.points) {
          lo = std::min(lo, p[1 - coordinate]);
          hi = std::max(hi, p[1 - coordinate]);
        }
        covered += hi - lo;
      }
    }
    if (!on_side) return false;
  }
  return covered >= 2 * (du + dv) - 4 * tol;
}

/// The parameter-plane loop of a curve on surface (142).
std::vector<surfaces::TrimCurve> trim_loop(const IgesFile& file, std::size_t pointer, const char* what) {
  const DirectoryEntry& e = file.entry(pointer, what);
  const auto c = file.parameters(e);
  if (e.type != kCurveOnSurface || c.size() < 3)
    file.fail(std::string("the ") + what + " is " + describe(e) + ", not a curve on surface (142)");
  if (c[2] == 0)
    file.fail(std::string("the ") + what + " (" + describe(e) +
              ") is given in space only, with no parameter-plane curve: not supported");
  std::vector<surfaces::TrimCurve> curves;
  collect_curves(file, whole_number(file, c[2], kMaxPointer, describe(e) + ": its curve pointer"), curves);
  return curves;
}

/// The patch of a trimmed surface (entity 144): its base surface (128) with the trimming loops,
/// none when the outer boundary is the domain's border (N1 = 0, or a curve along all of it)
/// and there are no holes.
surfaces::NurbsPatch trimmed_patch(const IgesFile& file, const DirectoryEntry& trimmed, std::size_t& base_line) {
  const auto v = file.parameters(trimmed);
  if (v.size() < 3) file.fail(describe(trimmed) + ": fewer than 3 parameters");
  const DirectoryEntry& base = file.entry(whole_number(file, v[0], kMaxPointer, describe(trimmed) + ": its surface pointer"),
                                         "trimmed surface's base surface");
  if (base.type != kSurface)
    file.fail("a trimmed surface (IGES entity 144) over IGES entity " + std::to_string(base.type) +
              ": envcrust reads rational B-spline surfaces (entity 128)");
  base_line = base.line;
  surfaces::NurbsPatch patch = read_surface(file, base);
  const std::size_t holes = whole_number(file, v[2], 1e6, describe(trimmed) + ": its hole count");
  if (v.size() < 4 + holes) file.fail(describe(trimmed) + ": fewer boundary curves than it counts");
  std::vector<surfaces::TrimCurve> outer;
  if (v[1] != 0)
    outer = trim_loop(file, whole_number(file, v[3], kMaxPointer, describe(trimmed) + ": its outer boundary pointer"),
                      "outer boundary");
  if (!outer.empty() && !is_domain_border(outer, *patch.parameter_range)) patch.trim_loops.push_back(std::move(outer));
  if (holes == 0 && patch.trim_loops.empty()) return patch;  // trimmed along its own border
  if (patch.trim_loops.empty()) {  // holes in the whole domain: its border is the outer loop
    const auto& r = *patch.parameter_range;
    patch.trim_loops.push_back({polyline_curve({{r[0], r[2]}, {r[1], r[2]}, {r[1], r[3]}, {r[0], r[3]}, {r[0], r[2]}})});
  }
  for (std::size_t h = 0; h < holes; ++h)
    patch.trim_loops.push_back(trim_loop(
        file, whole_number(file, v[4 + h], kMaxPointer, describe(trimmed) + ": a hole's pointer"), "inner boundary"));
  return patch;
}

}  // namespace

std::vector<surfaces::NurbsPatch> read_iges_patches(const std::filesystem::path& path) {
  const IgesFile file(path);
  // Entities 144 (their base, trimmed), and 128 no 144 uses, in the order of the directory.
  std::map<std::size_t, surfaces::NurbsPatch> found;
  std::set<std::size_t> bases;
  std::map<int, std::size_t> types;
  for (const auto& e : file.entries()) {
    ++types[e.type];
    if (e.type == kBounded)
      file.fail("a bounded surface (IGES entity 143): not supported; envcrust reads rational B-spline surfaces "
                "(entity 128), trimmed or not (144)");
    if (e.type == kTrimmed) {
      std::size_t base_line = 0;
      found.emplace(e.line, trimmed_patch(file, e, base_line));
      bases.insert(base_line);
    }
  }
  for (const auto& e : file.entries())
    if (e.type == kSurface && !bases.contains(e.line)) found.emplace(e.line, read_surface(file, e));
  if (found.empty()) {
    std::string list;
    for (const auto& [type, count] : types) list += (list.empty() ? "" : ", ") + std::to_string(type);
    file.fail("no rational B-spline surface (IGES entity 128) in the file (its entities: " + list + ")");
  }
  std::vector<surfaces::NurbsPatch> patches;
  for (auto& [line, patch] : found) patches.push_back(std::move(patch));
  return patches;
}

}  // namespace envcrust::io::detail
