// Sampled test curves for the knots tests: knots, links, rotations.
#pragma once

#include "envcrust/types.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace envcrust::knots::test {

inline constexpr double two_pi = 2.0 * std::numbers::pi;

/// n points of curve(t) at t = phase + 2 pi k / n.
inline Polyline sample(const std::function<Point3(double)>& curve, int n, double phase = 0.0) {
  Polyline out;
  for (int k = 0; k < n; ++k) {
    out.push_back(curve(phase + two_pi * k / n));
  }
  return out;
}

inline Point3 trefoil(double t) {
  return {std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)};
}

inline Point3 figure_eight(double t) {
  const double r = 2 + std::cos(2 * t);
  return {r * std::cos(3 * t), r * std::sin(3 * t), std::sin(4 * t)};
}

/// The figure-eight with the bump of docs/method.md §10.5, which switches its crossing at t = 5 pi / 6.
inline Point3 bumped_figure_eight(double t) {
  const Point3 p = figure_eight(t);
  const double u = (t - 5 * std::numbers::pi / 6) / 0.02;
  return {p.x(), p.y(), p.z() + 2.6 * std::exp(-u * u)};
}

/// Torus knot or link component wrapping p times around the z axis and q times around the tube.
inline Point3 torus_curve(double p, double q, double t, double tube_phase = 0.0) {
  const double r = 2 + std::cos(q * t + tube_phase);
  return {r * std::cos(p * t), r * std::sin(p * t), -std::sin(q * t + tube_phase)};
}

inline Polyline mirrored(Polyline curve) {
  for (Point3& p : curve) {
    p = Point3(p.x(), p.y(), -p.z());
  }
  return curve;
}

inline Polyline reversed(Polyline curve) {
  return Polyline(curve.rbegin(), curve.rend());
}

inline Polyline translated(Polyline curve, const Vector3& v) {
  for (Point3& p : curve) {
    p = p + v;
  }
  return curve;
}

/// The curve rotated by a random rotation (Gram-Schmidt on random vectors) and shifted.
inline Polyline randomly_rotated(const Polyline& curve, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vector3 e1(u(rng), u(rng), u(rng));
  e1 = e1 / std::sqrt(e1.squared_length());
  Vector3 e2(u(rng), u(rng), u(rng));
  e2 = e2 - (e2 * e1) * e1;
  e2 = e2 / std::sqrt(e2.squared_length());
  const Vector3 e3 = CGAL::cross_product(e1, e2);
  const Vector3 shift(u(rng), u(rng), u(rng));
  Polyline out;
  for (const Point3& p : curve) {
    const Vector3 v = p - CGAL::ORIGIN;
    out.push_back(CGAL::ORIGIN + Vector3(v * e1, v * e2, v * e3) + shift);
  }
  return out;
}

}  // namespace envcrust::knots::test
