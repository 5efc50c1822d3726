// Area-uniform random points on a surface by rejection sampling on the exact area element.
#include "builtin.h"
#include "vector_ops.h"

#include "envcrust/random.h"
#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

namespace envcrust::surfaces {

namespace {

constexpr int bound_grid = 128;
constexpr double bound_safety = 1.2;
constexpr int max_restarts = 32;

/// Uniform and normal variates from mt19937_64 by explicit transforms, because the standard
/// distributions are free to differ between standard libraries.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return uniform01(engine_); }

  /// Standard normal by Box-Muller; the second variate of each pair is kept for the next call.
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double radius = std::sqrt(-2.0 * std::log(1.0 - uniform()));  // 1 - U is in (0, 1]
    const double angle = 2 * std::numbers::pi * uniform();
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

std::string format_value(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

double area_element(const SurfaceJet& jet) { return norm(cross(jet.du, jet.dv)); }

/// Largest area element on a grid of nodes and cell centres.
double max_area_element(const Surface& surface, const ParameterDomain& d) {
  double best = 0;
  for (int i = 0; i <= 2 * bound_grid; ++i) {
    const double u = d.u0 + (d.u1 - d.u0) * i / (2 * bound_grid);
    for (int j = 0; j <= 2 * bound_grid; ++j) {
      const double v = d.v0 + (d.v1 - d.v0) * j / (2 * bound_grid);
      best = std::max(best, area_element(surface.evaluate(u, v)));
    }
  }
  return best;
}

}  // namespace

PointSet sample_surface(const Surface& surface, const SampleOptions& options) {
  if (options.count < 1) {
    throw InvalidOptions("sample count must be >= 1 (got " + std::to_string(options.count) + ")");
  }
  // Noise beyond the diagonal leaves no surface to sample; far beyond it, coordinates that
  // no stage accepts (or infinite ones).
  if (!(options.noise_rel_diag >= 0 && options.noise_rel_diag <= 1)) {
    throw InvalidOptions("noise must be in [0, 1], a fraction of the diagonal (got " +
                         format_value(options.noise_rel_diag) + ")");
  }
  const ParameterDomain d = surface.domain();
  double bound = bound_safety * max_area_element(surface, d);
  if (!(bound > 0) || !std::isfinite(bound)) {
    throw DegenerateInput("surface '" + surface.name() + "' has no area to sample");
  }

  PointSet result;
  for (int attempt = 0;; ++attempt) {
    // A sample above the bound would bias the distribution: raise the bound and start over
    // with the same seed, so the output stays a function of the seed alone.
    bool bound_exceeded = false;
    Random random(options.seed);
    result.points.clear();
    result.normals.clear();
    result.points.reserve(options.count);
    if (options.with_normals) result.normals.reserve(options.count);
    // A trimmed surface keeps part of its domain: a kept region too small to fill the count
    // in this many draws is refused rather than searched forever.
    const std::size_t max_draws = 10000 * options.count + 1000000;
    for (std::size_t draws = 0; result.points.size() < options.count; ++draws) {
      if (draws == max_draws)
        throw DegenerateInput("surface '" + surface.name() + "': its trimmed region has almost no area to sample");
      const double u = d.u0 + (d.u1 - d.u0) * random.uniform();
      const double v = d.v0 + (d.v1 - d.v0) * random.uniform();
      const SurfaceJet jet = surface.evaluate(u, v);
      const double element = area_element(jet);
      if (element > bound) {
        bound = 1.5 * element;
        bound_exceeded = true;
        break;
      }
      if (random.uniform() * bound >= element) continue;
      if (!surface.contains(u, v)) continue;
      result.points.push_back(jet.position);
      if (options.with_normals) {
        const Vector3 n = normalized(cross(jet.du, jet.dv));
        result.normals.push_back(dot(n, n) > 0 ? n : unit_normal_at(surface, u, v));
      }
    }
    if (!bound_exceeded) break;
    if (attempt == max_restarts) {
      throw NumericalFailure("sampling '" + surface.name() + "': area element is unbounded");
    }
  }

  if (options.noise_rel_diag > 0) add_noise(result.points, options.noise_rel_diag * bbox_diagonal(surface), options.seed);
  return result;
}

void add_noise(std::vector<Point3>& points, double sigma, std::uint64_t seed) {
  // A stream of its own, so that noisy and clean samples share their underlying points.
  Random noise(seed ^ 0x9E3779B97F4A7C15ULL);
  for (Point3& p : points) {
    const double dx = noise.normal(), dy = noise.normal(), dz = noise.normal();
    p = p + sigma * Vector3(dx, dy, dz);
  }
}

}  // namespace envcrust::surfaces
