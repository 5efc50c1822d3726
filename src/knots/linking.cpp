// Linking number of two closed polylines from the signed crossings of one generic projection.
#include "envcrust/errors.h"
#include "envcrust/knots.h"
#include "input.h"
#include "projection.h"
#include "simplify.h"

#include <random>

namespace envcrust::knots {
namespace {

constexpr int max_attempts = 20;

}  // namespace

int linking_number(const Polyline& a, const Polyline& b, const KnotOptions& options) {
  detail::validate_closed_polyline(a);
  detail::validate_closed_polyline(b);
  // Simplifying both loops together keeps them from passing through each other.
  const std::vector<Polyline> loops = detail::simplify_loops(
      {detail::remove_repeated_points(a), detail::remove_repeated_points(b)});
  std::mt19937_64 rng(options.seed);
  for (int attempt = 0; attempt < max_attempts; ++attempt) {
    const detail::Diagram diagram = detail::generic_diagram(loops, rng);
    int a_over_b = 0;
    int b_over_a = 0;
    for (const detail::Crossing& x : diagram.crossings) {
      const std::size_t over = diagram.loop_of(x.over_segment);
      const std::size_t under = diagram.loop_of(x.under_segment);
      if (over == 0 && under == 1) {
        a_over_b += x.sign;
      } else if (over == 1 && under == 0) {
        b_over_a += x.sign;
      }
    }
    // Equal for any consistent diagram of disjoint loops; a mismatch means the projection
    // misjudged a crossing, so another direction is tried.
    if (a_over_b == b_over_a) {
      return a_over_b;
    }
  }
  throw NumericalFailure("linking number: the over- and under-crossing sums never agreed in " +
                         std::to_string(max_attempts) + " projections");
}

}  // namespace envcrust::knots
