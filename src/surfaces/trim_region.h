// The kept region of a trimmed surface: closed loops of the parameter plane, even-odd inside.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace envcrust::surfaces {

using Uv = std::array<double, 2>;

/// Closed parameter-plane loops (first point not repeated) and a point-in-region test that
/// looks only at the loop segments of the query's horizontal band.
class TrimRegion {
 public:
  TrimRegion() = default;
  explicit TrimRegion(std::vector<std::vector<Uv>> loops);

  [[nodiscard]] bool empty() const { return loops_.empty(); }
  [[nodiscard]] const std::vector<std::vector<Uv>>& loops() const { return loops_; }
  /// Inside an odd number of loops (a ray towards +u crosses an odd number of segments).
  [[nodiscard]] bool contains(double u, double v) const;

 private:
  std::vector<std::vector<Uv>> loops_;
  std::vector<std::array<Uv, 2>> segments_;
  double v_lo_ = 0, band_height_ = 1;
  std::vector<std::vector<std::uint32_t>> bands_;  ///< per band, the segments that reach into it
};

/// Even-odd test of (u, v) against one closed loop.
bool is_inside_loop(const std::vector<Uv>& loop, double u, double v);

}  // namespace envcrust::surfaces
