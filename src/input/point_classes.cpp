// Points chosen by their classification attribute.
#include "point_classes.h"

#include "input_names.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace envcrust::input {
namespace {

std::string listed(const std::vector<int>& classes, const char* last_separator) {
  std::string text;
  for (std::size_t i = 0; i < classes.size(); ++i)
    text += (i == 0 ? "" : i + 1 == classes.size() ? last_separator : ", ") + std::to_string(classes[i]);
  return text;
}

}  // namespace

void keep_classes(AttributedPoints& points, const std::vector<int>& classes, const std::string& name,
                  std::vector<std::string>& notes) {
  if (classes.empty()) return;
  const auto& names = points.attributes.names;
  const auto column = std::find(names.begin(), names.end(), "classification");
  if (column == names.end())
    throw InvalidInput(named(name, "the points have no classification to choose classes " + listed(classes, ", ") +
                                       " from (LAS files have one, point files a column named 'classification')"));
  const std::vector<float>& of = points.attributes.scalars[static_cast<std::size_t>(column - names.begin())];
  std::vector<std::size_t> kept;
  std::map<float, std::size_t> present;  // class -> points
  for (std::size_t i = 0; i < of.size(); ++i) {
    ++present[of[i]];
    if (std::find(classes.begin(), classes.end(), of[i]) != classes.end()) kept.push_back(i);
  }
  if (kept.empty()) {
    std::string found;
    for (const auto& [value, count] : present) {
      std::ostringstream v;
      v << value;
      found += (found.empty() ? "" : ", ") + v.str() + " (" + std::to_string(count) + " points)";
    }
    throw InvalidInput(named(name, "no point is of class " + listed(classes, " or ") + " (the points' classes: " +
                                       found + ")"));
  }
  notes.push_back("kept the " + std::to_string(kept.size()) + " of " + std::to_string(of.size()) +
                  " points of class " + listed(classes, " or "));
  PointSet chosen;
  for (const std::size_t i : kept) {
    chosen.points.push_back(points.points.points[i]);
    if (points.points.has_normals()) chosen.normals.push_back(points.points.normals[i]);
  }
  points.attributes = points.attributes.pick(kept);
  points.points = std::move(chosen);
}

}  // namespace envcrust::input
