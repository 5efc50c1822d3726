// Per-point attributes of a scan (colours, intensity, any other column) and their transfer
// to the vertices of a reconstructed mesh.
//
// They are kept beside a PointSet, not in it, and out of TriangleMesh: the stages between
// reading and writing need positions and normals only, and should not carry a scan's
// columns through the envelope and the sheet.
#pragma once

#include "envcrust/types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace envcrust {

/// An 8-bit colour: red, green, blue.
using Colour = std::array<std::uint8_t, 3>;

/// Attributes of the points of a set, each empty or one value per point.
struct PointAttributes {
  std::vector<Colour> colours;              ///< empty or one per point
  std::vector<std::string> names;           ///< names of the scalar attributes ("intensity", ...)
  std::vector<std::vector<float>> scalars;  ///< one column per name, one value per point

  [[nodiscard]] bool empty() const { return colours.empty() && names.empty(); }
  [[nodiscard]] bool has_colours() const { return !colours.empty(); }

  /// The attributes of the points `picks` names, in that order (a subset, a reordering).
  [[nodiscard]] PointAttributes pick(const std::vector<std::size_t>& picks) const {
    PointAttributes out;
    out.names = names;
    out.scalars.resize(scalars.size());
    if (has_colours()) {
      out.colours.reserve(picks.size());
      for (const std::size_t i : picks) out.colours.push_back(colours[i]);
    }
    for (std::size_t c = 0; c < scalars.size(); ++c) {
      out.scalars[c].reserve(picks.size());
      for (const std::size_t i : picks) out.scalars[c].push_back(scalars[c][i]);
    }
    return out;
  }
};

/// A point set and the attributes of its points (io::read_attributed_points).
struct AttributedPoints {
  PointSet points;
  PointAttributes attributes;
};

namespace attributes {

/// For each target, the index of the nearest source point (of several at the same distance,
/// the kd-tree's choice, the same on every run). Empty when `sources` is.
std::vector<std::size_t> nearest_sources(const std::vector<Point3>& sources, const std::vector<Point3>& targets);

/// The attributes of `sources`' points carried to `targets`: each target takes those of its
/// nearest source point (colours exactly, no blend of neighbours).
PointAttributes carry_nearest(const std::vector<Point3>& sources, const PointAttributes& attributes,
                              const std::vector<Point3>& targets);

}  // namespace attributes
}  // namespace envcrust
