// Poisson-disk thinning on a hash grid.
#include "poisson_disk.h"

#include "envcrust/random.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace envcrust::envelope {
namespace {

struct CellKey {
  std::int64_t x, y, z;
  bool operator==(const CellKey&) const = default;
};

struct CellHash {
  std::size_t operator()(const CellKey& k) const {
    return static_cast<std::size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
  }
};

// 0 .. n-1 in a seeded random order (Fisher-Yates).
std::vector<std::size_t> shuffled_order(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937_64 rng(seed);
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[static_cast<std::size_t>(uniform01(rng) * static_cast<double>(i))]);
  return order;
}

// Cell offsets within `reach` cells, nearest first: a rejected candidate (most are) meets its
// conflict in the first few cells looked at. The decision does not depend on the order.
std::vector<CellKey> offsets_nearest_first(std::int64_t reach) {
  std::vector<CellKey> out;
  for (std::int64_t dx = -reach; dx <= reach; ++dx)
    for (std::int64_t dy = -reach; dy <= reach; ++dy)
      for (std::int64_t dz = -reach; dz <= reach; ++dz) out.push_back({dx, dy, dz});
  std::stable_sort(out.begin(), out.end(), [](const CellKey& a, const CellKey& b) {
    return a.x * a.x + a.y * a.y + a.z * a.z < b.x * b.x + b.y * b.y + b.z * b.z;
  });
  return out;
}

CellKey key_of(const Point3& p, double cell) {
  return CellKey{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                 static_cast<std::int64_t>(std::floor(p.y() / cell)),
                 static_cast<std::int64_t>(std::floor(p.z() / cell))};
}

}  // namespace

std::vector<std::size_t> poisson_disk_thin(const std::vector<Point3>& points, double radius,
                                           std::uint64_t seed) {
  const std::vector<std::size_t> order = shuffled_order(points.size(), seed);
  const double cell = radius / std::sqrt(3.0);
  const double r2 = radius * radius;
  std::unordered_map<CellKey, std::size_t, CellHash> grid;
  grid.reserve(points.size() / 4 + 16);
  std::vector<std::size_t> kept;
  // Kept points within `radius` lie at most 2 cells away (cell = radius / sqrt 3).
  const std::vector<CellKey> offsets = offsets_nearest_first(2);
  for (std::size_t index : order) {
    const Point3& p = points[index];
    const CellKey k = key_of(p, cell);
    bool free = true;
    for (const CellKey& d : offsets) {
      const auto it = grid.find({k.x + d.x, k.y + d.y, k.z + d.z});
      if (it != grid.end() && CGAL::squared_distance(points[it->second], p) <= r2) {
        free = false;
        break;
      }
    }
    if (free) {
      grid.emplace(k, index);
      kept.push_back(index);
    }
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

std::vector<std::size_t> poisson_disk_thin(const std::vector<Point3>& points, const std::vector<double>& radii,
                                           std::uint64_t seed) {
  const std::vector<std::size_t> order = shuffled_order(points.size(), seed);
  double largest = 0.0;
  for (double r : radii) largest = std::max(largest, r);
  if (!(largest > 0)) return {};
  // Cells of the largest radius / sqrt 3 hold several kept points where radii are small; a
  // query looks ceil(r / cell) cells around (at most 2, as in the uniform version).
  const double cell = largest / std::sqrt(3.0);
  std::unordered_map<CellKey, std::vector<std::size_t>, CellHash> grid;
  grid.reserve(points.size() / 4 + 16);
  std::vector<std::size_t> kept;
  const std::vector<CellKey> by_reach[3] = {offsets_nearest_first(0), offsets_nearest_first(1), offsets_nearest_first(2)};
  for (std::size_t index : order) {
    const Point3& p = points[index];
    const double r2 = radii[index] * radii[index];
    const auto reach = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::ceil(radii[index] / cell)), 0, 2);
    const CellKey k = key_of(p, cell);
    bool free = true;
    for (const CellKey& d : by_reach[reach]) {
      const auto it = grid.find({k.x + d.x, k.y + d.y, k.z + d.z});
      if (it == grid.end()) continue;
      for (std::size_t other : it->second)
        if (CGAL::squared_distance(points[other], p) <= r2) {
          free = false;
          break;
        }
      if (!free) break;
    }
    if (free) {
      grid[k].push_back(index);
      kept.push_back(index);
    }
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace envcrust::envelope
