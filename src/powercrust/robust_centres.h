// Circumcentres and power vertices that stay accurate where doubles lose every digit.
#pragma once

#include "envcrust/types.h"

namespace envcrust::powercrust {

/// The point of equal power to four weighted points (a power-diagram vertex). Interval
/// arithmetic first; exact rationals when the interval is wide (nearly coincident balls, as
/// the inner poles of a sphere sample, cancel every digit of the double formula). With zero
/// weights it is the circumcentre.
Point3 power_vertex(const Kernel::Weighted_point_3& p, const Kernel::Weighted_point_3& q,
                    const Kernel::Weighted_point_3& r, const Kernel::Weighted_point_3& s);

}  // namespace envcrust::powercrust
