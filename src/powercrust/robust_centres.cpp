// Power vertices by interval arithmetic with an exact fallback, deterministic to the bit.
#include "robust_centres.h"

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/constructions/kernel_ftC3.h>

#include <algorithm>
#include <cmath>

namespace envcrust::powercrust {
namespace {

// Accept the interval result when it is this tight relative to the inputs' magnitude.
constexpr double kRelativeWidth = 1e-13;

template <class FT>
void solve(const Kernel::Weighted_point_3& p, const Kernel::Weighted_point_3& q,
           const Kernel::Weighted_point_3& r, const Kernel::Weighted_point_3& s, FT& x, FT& y, FT& z) {
  auto c = [](double v) { return FT(v); };
  CGAL::weighted_circumcenterC3(
      c(p.x()), c(p.y()), c(p.z()), c(p.weight()), c(q.x()), c(q.y()), c(q.z()), c(q.weight()),
      c(r.x()), c(r.y()), c(r.z()), c(r.weight()), c(s.x()), c(s.y()), c(s.z()), c(s.weight()), x, y, z);
}

}  // namespace

Point3 power_vertex(const Kernel::Weighted_point_3& p, const Kernel::Weighted_point_3& q,
                    const Kernel::Weighted_point_3& r, const Kernel::Weighted_point_3& s) {
  double scale = 0;
  for (const auto* w : {&p, &q, &r, &s})
    scale = std::max({scale, std::abs(w->x()), std::abs(w->y()), std::abs(w->z()),
                      std::sqrt(std::max(0.0, w->weight()))});
  {
    using Interval = CGAL::Interval_nt<>;
    Interval x, y, z;
    solve(p, q, r, s, x, y, z);
    const double tolerance = kRelativeWidth * scale;
    auto tight = [&](const Interval& i) {
      return std::isfinite(i.inf()) && std::isfinite(i.sup()) && i.sup() - i.inf() <= tolerance;
    };
    if (tight(x) && tight(y) && tight(z))
      return Point3(CGAL::to_double(x), CGAL::to_double(y), CGAL::to_double(z));
  }
  CGAL::Exact_rational x, y, z;
  solve(p, q, r, s, x, y, z);
  return Point3(CGAL::to_double(x), CGAL::to_double(y), CGAL::to_double(z));
}

}  // namespace envcrust::powercrust
