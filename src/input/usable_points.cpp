// A point set as read, made usable by the stages.
#include "usable_points.h"

#include "input_names.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <utility>

namespace envcrust::input {
namespace {

// Six columns whose last three are whole numbers in 0..255 on every line, some above 1:
// colours (x y z r g b, a common export), which read as normals would all point into one
// octant and set every envelope sample wrong.
bool columns_look_like_colours(const std::vector<Vector3>& normals) {
  if (normals.empty()) return false;
  bool above_one = false;
  for (const Vector3& n : normals) {
    for (const double c : {n.x(), n.y(), n.z()}) {
      if (!(c >= 0 && c <= 255 && c == std::floor(c))) return false;
      above_one = above_one || c > 1;
    }
  }
  return above_one;
}

// Six columns of colours read as normals become the points' colours.
void normals_to_colours(PointSet& read, PointAttributes& attributes) {
  attributes.colours.clear();
  for (const Vector3& n : read.normals)
    attributes.colours.push_back({static_cast<std::uint8_t>(n.x()), static_cast<std::uint8_t>(n.y()),
                                  static_cast<std::uint8_t>(n.z())});
  read.normals.clear();
}

}  // namespace

AttributedPoints usable_points(AttributedPoints input, bool are_normals_text_columns, const std::string& name,
                               std::vector<std::string>& notes) {
  PointSet& read = input.points;
  if (are_normals_text_columns && columns_look_like_colours(read.normals)) {
    normals_to_colours(read, input.attributes);
    notes.push_back("columns 4-6 are whole numbers in 0..255 on every line: read as colours, not normals");
  } else if (!read.normals.empty() && std::all_of(read.normals.begin(), read.normals.end(),
                                                  [](const Vector3& n) { return n == Vector3(0, 0, 0); })) {
    // Exporters write (0, 0, 0) where they have no normals: none given, not each one zero.
    read.normals.clear();
    notes.push_back("every normal in the file is zero: read as no normals");
  }
  for (std::size_t i = 0; i < read.normals.size(); ++i) {
    const double length = std::sqrt(read.normals[i].squared_length());
    if (!(length > 0) || !std::isfinite(length))
      throw InvalidInput(named(name, "point " + std::to_string(i + 1) + " has a zero normal"));
    read.normals[i] = read.normals[i] / length;
  }
  mesh::MergedPoints merged = naming(name, [&] { return mesh::merge_duplicate_points(read.points); });
  AttributedPoints result;
  PointSet& out = result.points;
  out.points = std::move(merged.points);
  if (read.has_normals()) {
    std::vector<char> seen(out.points.size(), 0);
    for (std::size_t i = 0; i < read.points.size(); ++i)
      if (const Index k = merged.input_to_merged[i]; !seen[k]) seen[k] = 1, out.normals.push_back(read.normals[i]);
  }
  if (!input.attributes.empty()) {
    std::vector<std::size_t> first(out.points.size(), read.points.size());  // the input point of each merged one
    for (std::size_t i = read.points.size(); i-- > 0;) first[merged.input_to_merged[i]] = i;
    result.attributes = input.attributes.pick(first);
  }
  if (merged.duplicates > 0) notes.push_back(std::to_string(merged.duplicates) + " duplicate points merged");
  const std::size_t n = out.points.size();
  if (n < 5)
    throw DegenerateInput(named(name, "need at least 5 distinct points, got " + std::to_string(n) +
                                          (merged.duplicates > 0 ? " (" + std::to_string(merged.duplicates) +
                                                                       " duplicates merged)"
                                                                 : "")));
  // Within 1e-5 of their size of a line (6 printed significant digits leave a line within
  // about 1.5e-6 of it): a curve.
  const double diagonal = mesh::bbox_diagonal(out.points);
  if (mesh::spread_dimension(out.points, 1e-5 * diagonal) < 2) {
    std::ostringstream s;
    s << std::setprecision(3) << "all " << n << " points lie on a line (within 1e-5 of their extent, " << diagonal
      << "): no surface to reconstruct";
    throw DegenerateInput(named(name, s.str()));
  }
  return result;
}

}  // namespace envcrust::input
