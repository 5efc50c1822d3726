// Global measures of a surface: bounding-box diagonal and area by Gauss-Legendre quadrature.
#include "builtin.h"
#include "vector_ops.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace envcrust::surfaces {

namespace {

// 8-point Gauss-Legendre rule on [-1, 1].
constexpr std::array<double, 8> gauss_nodes{
    -0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
    0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
constexpr std::array<double, 8> gauss_weights{
    0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
    0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

// A multiple of 4 so that panel ends fall on the NURBS circle's quarter knots, where the
// integrand is only C^1.
constexpr int panels = 64;
constexpr int bbox_grid = 256;

}  // namespace

double bbox_diagonal(const Surface& surface) {
  const ParameterDomain d = surface.domain();
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  const auto grow = [&](const Point3& p) {
    for (int k = 0; k < 3; ++k) {
      const auto uk = static_cast<std::size_t>(k);
      lo[uk] = std::min(lo[uk], p[k]);
      hi[uk] = std::max(hi[uk], p[k]);
    }
  };
  for (int i = 0; i <= bbox_grid; ++i) {
    const double u = d.u0 + (d.u1 - d.u0) * i / bbox_grid;
    for (int j = 0; j <= bbox_grid; ++j) {
      const double v = d.v0 + (d.v1 - d.v0) * j / bbox_grid;
      if (surface.contains(u, v)) grow(surface.evaluate(u, v).position);
    }
  }
  for (const auto& loop : surface.trim_loops())
    for (const auto& [u, v] : loop) grow(surface.evaluate(u, v).position);
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

double area(const Surface& surface) {
  const ParameterDomain d = surface.domain();
  const double hu = (d.u1 - d.u0) / panels;
  const double hv = (d.v1 - d.v0) / panels;
  double total = 0;
  for (int pu = 0; pu < panels; ++pu) {
    for (std::size_t a = 0; a < gauss_nodes.size(); ++a) {
      const double u = d.u0 + hu * (pu + 0.5 * (gauss_nodes[a] + 1));
      double column = 0;
      for (int pv = 0; pv < panels; ++pv) {
        for (std::size_t b = 0; b < gauss_nodes.size(); ++b) {
          const double v = d.v0 + hv * (pv + 0.5 * (gauss_nodes[b] + 1));
          const SurfaceJet jet = surface.evaluate(u, v);
          if (surface.contains(u, v)) column += gauss_weights[b] * norm(cross(jet.du, jet.dv));
        }
      }
      total += gauss_weights[a] * column;
    }
  }
  return total * 0.25 * hu * hv;
}

}  // namespace envcrust::surfaces
