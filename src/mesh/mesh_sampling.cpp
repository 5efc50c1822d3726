// Area-uniform random points on a triangle mesh (seeded, portable across standard libraries).
#include "envcrust/random.h"
#include "envcrust/mesh.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace envcrust::mesh {
std::vector<Point3> sample_by_area(const TriangleMesh& mesh, std::size_t count,
                                   std::uint64_t seed) {
  std::vector<Point3> out;
  if (mesh.triangles.empty() || count == 0) return out;
  std::vector<double> cumulative(mesh.triangles.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    sum += std::sqrt(
        Kernel::Triangle_3(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]])
            .squared_area());
    cumulative[i] = sum;
  }
  if (!(sum > 0.0)) return out;
  std::mt19937_64 rng(seed);
  out.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double target = uniform01(rng) * sum;
    auto it = std::upper_bound(cumulative.begin(), cumulative.end(), target);
    if (it == cumulative.end()) --it;
    const auto& t = mesh.triangles[static_cast<std::size_t>(it - cumulative.begin())];
    double r1 = uniform01(rng);
    double r2 = uniform01(rng);
    if (r1 + r2 > 1.0) {
      r1 = 1.0 - r1;
      r2 = 1.0 - r2;
    }
    const Point3& a = mesh.vertices[t[0]];
    const Point3& b = mesh.vertices[t[1]];
    const Point3& c = mesh.vertices[t[2]];
    out.push_back(a + r1 * (b - a) + r2 * (c - a));
  }
  return out;
}

}  // namespace envcrust::mesh
