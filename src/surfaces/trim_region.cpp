// Point-in-region tests for trimmed surfaces, banded so that a query visits few segments.
#include "trim_region.h"

#include <algorithm>
#include <cmath>

namespace envcrust::surfaces {

namespace {

/// Whether the segment a-b crosses the ray from (u, v) towards +u (half-open in v).
bool crosses(const Uv& a, const Uv& b, double u, double v) {
  if ((a[1] > v) == (b[1] > v)) return false;
  const double at = a[0] + (v - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
  return u < at;
}

}  // namespace

bool is_inside_loop(const std::vector<Uv>& loop, double u, double v) {
  bool inside = false;
  for (std::size_t k = 0; k < loop.size(); ++k)
    if (crosses(loop[k], loop[(k + 1) % loop.size()], u, v)) inside = !inside;
  return inside;
}

TrimRegion::TrimRegion(std::vector<std::vector<Uv>> loops) : loops_(std::move(loops)) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& loop : loops_)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      segments_.push_back({loop[k], loop[(k + 1) % loop.size()]});
      lo = std::min(lo, loop[k][1]);
      hi = std::max(hi, loop[k][1]);
    }
  if (segments_.empty()) return;
  // About 8 segments per band on average.
  const std::size_t count = std::clamp<std::size_t>(segments_.size() / 8, 1, 4096);
  v_lo_ = lo;
  band_height_ = hi > lo ? (hi - lo) / static_cast<double>(count) : 1.0;
  bands_.assign(count, {});
  const auto band_of = [&](double v) {
    return std::min(count - 1, static_cast<std::size_t>(std::max(0.0, std::floor((v - v_lo_) / band_height_))));
  };
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const auto [a, b] = segments_[s];
    for (std::size_t band = band_of(std::min(a[1], b[1])); band <= band_of(std::max(a[1], b[1])); ++band)
      bands_[band].push_back(static_cast<std::uint32_t>(s));
  }
}

bool TrimRegion::contains(double u, double v) const {
  if (bands_.empty()) return true;
  if (v < v_lo_ || v > v_lo_ + band_height_ * static_cast<double>(bands_.size())) return false;
  const auto band = std::min(bands_.size() - 1, static_cast<std::size_t>(std::floor((v - v_lo_) / band_height_)));
  bool inside = false;
  for (const std::uint32_t s : bands_[band])
    if (crosses(segments_[s][0], segments_[s][1], u, v)) inside = !inside;
  return inside;
}

}  // namespace envcrust::surfaces
