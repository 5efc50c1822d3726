// Small inline vector helpers on the kernel's Vector3 shared by the surfaces module.
#pragma once

#include "envcrust/types.h"

#include <cmath>

namespace envcrust::surfaces {

inline double dot(const Vector3& a, const Vector3& b) {
  return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
}

inline Vector3 cross(const Vector3& a, const Vector3& b) {
  return Vector3(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(),
                 a.x() * b.y() - a.y() * b.x());
}

inline double norm(const Vector3& a) { return std::sqrt(dot(a, a)); }

/// a / |a|, or the zero vector when |a| vanishes.
inline Vector3 normalized(const Vector3& a) {
  const double length = norm(a);
  return length > 0 ? a / length : Vector3(0, 0, 0);
}

}  // namespace envcrust::surfaces
