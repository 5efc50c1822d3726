// Candidate generation on the three parts of the envelope (docs/method.md §5.1).
#include "envelope_candidates.h"
#include "input_tree.h"

#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"
#include "envcrust/random.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace envcrust::envelope {
namespace {


constexpr unsigned kNeighbors = 8;  // r_k of the 8th neighbour covers the gaps of random samples

Vector3 unit(const Vector3& v) {
  const double len = std::sqrt(v.squared_length());
  return len > 0 ? v / len : v;
}

// Any unit vector perpendicular to n.
Vector3 perpendicular(const Vector3& n) {
  const Vector3 a = std::abs(n.x()) < 0.9 ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
  return unit(CGAL::cross_product(n, a));
}

void add_pair(std::vector<EnvelopeSample>& out, const Point3& g, const Vector3& n, double rho,
              EnvelopePart part, int curve) {
  out.push_back({g + rho * n, g, n, part, curve});
  out.push_back({g - rho * n, g, -n, part, curve});
}

}  // namespace

NeighbourDistances neighbour_distances(const std::vector<Point3>& points, const PointTree& tree) {
  NeighbourDistances out;
  out.nearest.assign(points.size(), 0.0);
  out.rk.assign(points.size(), 0.0);
  if (points.empty()) return out;
  const unsigned k = std::min<unsigned>(kNeighbors + 1, static_cast<unsigned>(points.size()));
  // Queries along a Hilbert curve: consecutive ones visit the same part of the tree (each
  // result is the same in any order).
  const std::vector<std::size_t> order = mesh::hilbert_order(points);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1024), [&](const auto& r) {
    for (std::size_t at = r.begin(); at != r.end(); ++at) {
      const std::size_t i = order[at];
      // Hits come nearest first; the first is the sample itself (or a duplicate of it).
      PointSearch search(tree, points[i], k);
      unsigned rank = 0;
      double rk2 = 0.0;
      for (const auto& hit : search) {
        if (rank++ == 1) out.nearest[i] = std::sqrt(hit.second);
        rk2 = std::max(rk2, hit.second);
      }
      out.rk[i] = std::sqrt(rk2);
    }
  });
  return out;
}

std::vector<EnvelopeSample> sheet_candidates(const SurfaceSamples& s, const std::vector<double>& rho,
                                             double spacing_rel_rho, double per_h2, std::uint64_t seed,
                                             const std::vector<double>& rk_of) {
  // Generators spread over a tangent disk must stay on M: near a boundary curve, drop those
  // beyond it (the rim covers that part of the envelope).
  std::vector<Point3> rim_points;
  std::vector<Vector3> rim_conormals;
  for (const auto& curve : s.boundary)
    for (const auto& b : curve.vertices) {
      rim_points.push_back(b.position);
      rim_conormals.push_back(b.conormal);
    }
  const NearestIndex rim_index(rim_points);
  auto beyond_boundary = [&](const Point3& g) {
    if (rim_index.empty()) return false;
    const auto [b, d] = rim_index.nearest(g);
    return (g - rim_points[b]) * rim_conormals[b] > 0.0;
  };
  // The generators in input order (one random stream).
  std::mt19937_64 rng(seed);
  std::vector<EnvelopeSample> out;
  out.reserve(4 * s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Point3& p = s.points[i];
    const Vector3 n = unit(s.normals[i]);
    const double rk = rk_of[i];
    const double rk2 = rk * rk;
    const double h = spacing_rel_rho * rho[i];
    // Disks of radius r_k overlap about k times, so m generators per disk give a density of
    // about k m / (pi r_k^2); ask for per_h2 / h^2.
    const double wanted = per_h2 * std::numbers::pi * rk2 / (kNeighbors * h * h);
    // Input denser than the envelope needs (wanted < 1 generator per point): keep the point
    // with probability `wanted`, so the candidates stay about per_h2 per h^2 and their count
    // stops growing with the input's (trefoil ribbon, 1M points: 2M candidates for 15k samples).
    if (wanted < 1.0 && uniform01(rng) >= wanted) continue;
    const int m = std::clamp(static_cast<int>(std::ceil(wanted)), 1, 64);
    const Vector3 e1 = perpendicular(n);
    const Vector3 e2 = CGAL::cross_product(n, e1);
    add_pair(out, p, n, rho[i], EnvelopePart::Sheet, -1);
    for (int k = 1; k < m; ++k) {
      const double r = rk * std::sqrt(uniform01(rng));
      const double a = 2.0 * std::numbers::pi * uniform01(rng);
      const Point3 g = p + r * std::cos(a) * e1 + r * std::sin(a) * e2;
      if (!beyond_boundary(g)) add_pair(out, g, n, rho[i], EnvelopePart::Sheet, -1);
    }
  }
  return out;
}

namespace {

// How one boundary segment a -> b is swept: rings `step` apart along it (`pieces`), each a
// half-circle of `arcs` + 1 candidates, and at a convex corner `sweeps` - 1 half-circles of
// the lune.
struct RimSegment {
  double step = 0.0;
  int arcs = 0, pieces = 0, sweeps = 0;
};

RimSegment rim_segment(const BoundaryVertex& a, const BoundaryVertex& b, double rho, double spacing_rel_rho,
                       double step_rel_h) {
  RimSegment r;
  r.step = step_rel_h * (spacing_rel_rho * rho);
  // Counted in doubles first: a tiny rho must not overflow the int.
  r.arcs = static_cast<int>(std::clamp(std::ceil(std::numbers::pi * rho / r.step), 4.0, 1e9));
  const double len = std::sqrt(CGAL::squared_distance(a.position, b.position));
  r.pieces = static_cast<int>(std::clamp(std::ceil(len / r.step), 1.0, 1e9));
  if (a.is_corner && a.tangent * a.conormal_next > 0) {
    const double angle = std::acos(std::clamp(a.conormal * a.conormal_next, -1.0, 1.0));
    r.sweeps = static_cast<int>(std::clamp(std::ceil(angle * rho / r.step), 1.0, 1e9));
  }
  return r;
}

}  // namespace

double rim_candidate_count(const std::vector<BoundaryCurve>& boundary,
                           const std::vector<std::vector<double>>& rim_rho, double spacing_rel_rho,
                           double step_rel_h) {
  double count = 0.0;
  for (std::size_t ci = 0; ci < boundary.size(); ++ci) {
    const auto& vertices = boundary[ci].vertices;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const RimSegment r = rim_segment(vertices[i], vertices[(i + 1) % vertices.size()], rim_rho[ci][i],
                                       spacing_rel_rho, step_rel_h);
      count += double(r.pieces) * (r.arcs + 1) + std::max(0.0, double(r.sweeps) - 1) * (r.arcs - 1);
    }
  }
  return count;
}

std::vector<EnvelopeSample> rim_candidates(const std::vector<BoundaryCurve>& boundary,
                                           const std::vector<std::vector<double>>& rim_rho,
                                           double spacing_rel_rho, double step_rel_h) {
  std::vector<EnvelopeSample> out;
  for (std::size_t ci = 0; ci < boundary.size(); ++ci) {
    const auto& vertices = boundary[ci].vertices;
    const int curve = static_cast<int>(ci);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      // The segment from vertex i takes vertex i's rho (adaptive rho is Lipschitz, so its
      // neighbour's differs little).
      const double rho = rim_rho[ci][i];
      const BoundaryVertex& a = vertices[i];
      const BoundaryVertex& b = vertices[(i + 1) % vertices.size()];
      const RimSegment segment = rim_segment(a, b, rho, spacing_rel_rho, step_rel_h);
      const int arcs = segment.arcs, pieces = segment.pieces, sweeps = segment.sweeps;
      // Conormal leaving a corner is conormal_next; the segment interpolates to b's arriving one.
      const Vector3 ca = a.is_corner ? a.conormal_next : a.conormal;
      Vector3 nb = b.normal;
      if (nb * a.normal < 0) nb = -nb;  // normal lines: make neighbours agree before blending
      Vector3 cb = b.conormal;
      for (int k = 0; k < pieces; ++k) {
        const double f = static_cast<double>(k) / pieces;
        const Point3 g = a.position + f * (b.position - a.position);
        const Vector3 n = unit((1 - f) * a.normal + f * nb);
        Vector3 c = (1 - f) * ca + f * cb;
        c = unit(c - (c * n) * n);
        for (int j = 0; j <= arcs; ++j) {
          const double theta = std::numbers::pi * j / arcs;
          const Vector3 u = unit(std::cos(theta) * n + std::sin(theta) * c);
          out.push_back({g + rho * u, g, u, EnvelopePart::Rim, curve});
        }
      }
      // Lune at a convex corner: the arriving edge runs out past the leaving edge's side.
      if (sweeps > 0) {
        for (int s = 1; s < sweeps; ++s) {
          const double f = static_cast<double>(s) / sweeps;
          const Vector3 d = unit((1 - f) * a.conormal + f * a.conormal_next);
          for (int j = 1; j < arcs; ++j) {
            const double phi = std::numbers::pi * j / arcs;
            const Vector3 u = unit(std::cos(phi) * a.normal + std::sin(phi) * d);
            out.push_back({a.position + rho * u, a.position, u, EnvelopePart::Corner, curve});
          }
        }
      }
    }
  }
  return out;
}

}  // namespace envcrust::envelope
