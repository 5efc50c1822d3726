// Generic planar projections of closed polylines: random rotations, crossings, genericity checks.
#pragma once

#include "envcrust/types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace envcrust::knots::detail {

/// A 3 x 3 rotation matrix, row-major.
using Rotation = std::array<double, 9>;

/// A uniformly distributed random rotation (Shoemake's quaternion method) drawn with a
/// hand-written uniform transform, so the sequence is the same on every standard library.
Rotation random_rotation(std::mt19937_64& rng);

/// One crossing of the projected diagram. Segments are numbered globally: segment k of loop L
/// is (loop_start[L] + k) and runs from vertex k to vertex k + 1 (mod the loop's size).
struct Crossing {
  std::uint32_t over_segment = 0;
  std::uint32_t under_segment = 0;
  double over_param = 0.0;   ///< position along the over segment, in (0, 1)
  double under_param = 0.0;  ///< position along the under segment, in (0, 1)
  int sign = 0;              ///< sign((d_over x d_under) . z): +1 or -1
};

/// A link diagram: the loops' layout and the crossings of their projection to the xy plane.
struct Diagram {
  std::vector<std::uint32_t> loop_start;  ///< first global segment of each loop, plus the total
  std::vector<Crossing> crossings;

  /// The loop a global segment belongs to.
  [[nodiscard]] std::size_t loop_of(std::uint32_t segment) const;
};

/// The diagram of the loops projected along the rotated z axis (the first two rows of
/// `rotation` give the xy coordinates, about the loops' bounding-box centre), or nothing if the
/// projection is not generic: a vertex within 1e-9 * diag of a non-incident segment, or two
/// crossings within that distance of each other. Which strand is over is decided exactly from
/// the original points (CGAL::orientation), not from rounded heights; segments that meet in
/// space also make the projection non-generic.
std::optional<Diagram> project_loops(const std::vector<Polyline>& loops, const Rotation& rotation);

/// The first generic diagram among random rotations drawn from rng.
/// @throws NumericalFailure if none of many rotations gives a generic projection.
Diagram generic_diagram(const std::vector<Polyline>& loops, std::mt19937_64& rng);

/// The diagram with the fewest crossings among `candidates` generic diagrams (first wins ties).
/// @throws NumericalFailure as generic_diagram.
Diagram simplest_generic_diagram(const std::vector<Polyline>& loops, std::mt19937_64& rng,
                                 int candidates);

}  // namespace envcrust::knots::detail
