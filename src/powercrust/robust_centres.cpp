// Power vertices by interval arithmetic with an exact fallback, deterministic to the bit.
#include "robust_centres.h"

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/constructions/kernel_ftC3.h>

#include <algorithm>
#include <cmath>

namespace envcrust::powercrust {
namespace {

// Accept the interval result when it is this tight relative to the inputs' magnitude: far
// below any geometric scale of the crust, and wide enough that only near-degenerate cells
// (nearly coincident balls) pay for exact arithmetic.
constexpr double kRelativeWidth = 1e-10;

// The numerators and denominator of CGAL's weighted circumcentre: ring operations only, so
// Mpzf computes them exactly.
template <class FT>
void determinants(const Kernel::Weighted_point_3& p, const Kernel::Weighted_point_3& q,
                  const Kernel::Weighted_point_3& r, const Kernel::Weighted_point_3& s, FT& num_x,
                  FT& num_y, FT& num_z, FT& den) {
  auto c = [](double v) { return FT(v); };
  CGAL::determinants_for_weighted_circumcenterC3(
      c(p.x()), c(p.y()), c(p.z()), c(p.weight()), c(q.x()), c(q.y()), c(q.z()), c(q.weight()),
      c(r.x()), c(r.y()), c(r.z()), c(r.weight()), c(s.x()), c(s.y()), c(s.z()), c(s.weight()),
      num_x, num_y, num_z, den);
}

}  // namespace

Point3 power_vertex(const Kernel::Weighted_point_3& p, const Kernel::Weighted_point_3& q,
                    const Kernel::Weighted_point_3& r, const Kernel::Weighted_point_3& s) {
  double scale = 0;
  for (const auto* w : {&p, &q, &r, &s})
    scale = std::max({scale, std::abs(w->x()), std::abs(w->y()), std::abs(w->z()),
                      std::sqrt(std::max(0.0, w->weight()))});
  {
    // One switch of the rounding mode for the whole evaluation (Interval_nt<true> switches it
    // around every operation); the guard restores it before the result is rounded to doubles.
    using Interval = CGAL::Interval_nt<false>;
    double lo[3], hi[3];
    bool usable = false;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      Interval nx, ny, nz, den;
      determinants(p, q, r, s, nx, ny, nz, den);
      if (!CGAL::possibly(den == 0)) {
        const Interval inv = 1 / (2 * den);
        const Interval c[3] = {p.x() + nx * inv, p.y() - ny * inv, p.z() + nz * inv};
        usable = true;
        for (int k = 0; k < 3; ++k) lo[k] = c[k].inf(), hi[k] = c[k].sup();
      }
    }
    if (usable) {
      const double tolerance = kRelativeWidth * scale;
      bool tight = true;
      for (int k = 0; k < 3; ++k) tight = tight && hi[k] - lo[k] <= tolerance;
      // The interval's midpoint, rounded to nearest (what to_double of the interval gives).
      if (tight) return Point3((hi[0] + lo[0]) * 0.5, (hi[1] + lo[1]) * 0.5, (hi[2] + lo[2]) * 0.5);
    }
  }
  // Exact determinants, one rounding each: accurate to a few ulps whatever the cancellation.
  CGAL::Mpzf nx, ny, nz, den;
  determinants(p, q, r, s, nx, ny, nz, den);
  const double d = 2 * CGAL::to_double(den);
  return Point3(p.x() + CGAL::to_double(nx) / d, p.y() - CGAL::to_double(ny) / d,
                p.z() + CGAL::to_double(nz) / d);
}

}  // namespace envcrust::powercrust
