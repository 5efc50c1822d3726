// Delta-move simplification of closed polylines with exact CGAL predicates and a uniform grid.
#include "simplify.h"

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace envcrust::knots::detail {
namespace {

using Triangle3 = Kernel::Triangle_3;
using Segment3 = Kernel::Segment_3;

/// Buckets segments (named by their start vertex) by the cells their bounding boxes cover.
class SegmentGrid {
 public:
  SegmentGrid(const CGAL::Bbox_3& domain, double cell_size, std::size_t max_cells) {
    lo_ = {domain.xmin(), domain.ymin(), domain.zmin()};
    const std::array<double, 3> extent = {domain.xmax() - domain.xmin(),
                                          domain.ymax() - domain.ymin(),
                                          domain.zmax() - domain.zmin()};
    double h = std::max(cell_size, 1e-300);
    for (;;) {
      std::size_t total = 1;
      for (int k = 0; k < 3; ++k) {
        const double cells = std::ceil(extent[k] / h);
        dims_[k] = static_cast<std::size_t>(std::clamp(cells, 1.0, 1024.0));
        total *= dims_[k];
      }
      if (total <= max_cells) {
        break;
      }
      h *= 1.5;
    }
    inv_h_ = 1.0 / h;
    cells_.resize(dims_[0] * dims_[1] * dims_[2]);
  }

  void insert(std::uint32_t segment, const CGAL::Bbox_3& box) {
    for_each_cell(box, [&](std::vector<std::uint32_t>& cell) { cell.push_back(segment); });
  }

  template <typename Visit>
  void for_each_cell(const CGAL::Bbox_3& box, Visit&& visit) {
    const std::array<double, 3> bmin = {box.xmin(), box.ymin(), box.zmin()};
    const std::array<double, 3> bmax = {box.xmax(), box.ymax(), box.zmax()};
    std::array<std::size_t, 3> from{};
    std::array<std::size_t, 3> to{};
    for (int k = 0; k < 3; ++k) {
      from[k] = cell_of(bmin[k], k);
      to[k] = cell_of(bmax[k], k);
    }
    for (std::size_t x = from[0]; x <= to[0]; ++x) {
      for (std::size_t y = from[1]; y <= to[1]; ++y) {
        for (std::size_t z = from[2]; z <= to[2]; ++z) {
          visit(cells_[(x * dims_[1] + y) * dims_[2] + z]);
        }
      }
    }
  }

 private:
  // Monotone in the coordinate, so overlapping boxes always share a cell.
  [[nodiscard]] std::size_t cell_of(double value, int axis) const {
    const double cell = std::floor((value - lo_[axis]) * inv_h_);
    return static_cast<std::size_t>(std::clamp(cell, 0.0, static_cast<double>(dims_[axis] - 1)));
  }

  std::array<double, 3> lo_{};
  std::array<std::size_t, 3> dims_{};
  double inv_h_ = 1.0;
  std::vector<std::vector<std::uint32_t>> cells_;
};

/// Does segment (shared, far) enter the non-degenerate triangle (shared, t1, t2) anywhere but
/// at the shared vertex? Only possible when far is in the triangle's plane and inside the angle
/// at the shared vertex; boundary cases count as entering (conservative).
bool adjacent_enters(const Point3& shared, const Point3& t1, const Point3& t2, const Point3& far) {
  if (CGAL::orientation(shared, t1, t2, far) != CGAL::COPLANAR) {
    return false;
  }
  return CGAL::coplanar_orientation(shared, t1, t2, far) != CGAL::NEGATIVE &&
         CGAL::coplanar_orientation(shared, t2, t1, far) != CGAL::NEGATIVE;
}

class Simplifier {
 public:
  explicit Simplifier(const std::vector<Polyline>& loops) {
    for (const Polyline& loop : loops) {
      const auto first = static_cast<std::uint32_t>(points_.size());
      const auto n = static_cast<std::uint32_t>(loop.size());
      for (std::uint32_t i = 0; i < n; ++i) {
        points_.push_back(loop[i]);
        next_.push_back(first + (i + 1) % n);
        prev_.push_back(first + (i + n - 1) % n);
        loop_of_.push_back(static_cast<std::uint32_t>(loop_size_.size()));
      }
      loop_size_.push_back(n);
    }
    alive_.assign(points_.size(), true);
    changed_.assign(points_.size(), false);
    stamp_.assign(points_.size(), 0);
  }

  void run() {
    while (pass()) {
    }
  }

  [[nodiscard]] std::vector<Polyline> result() const {
    std::vector<Polyline> loops(loop_size_.size());
    std::vector<bool> done(loop_size_.size(), false);
    for (std::uint32_t v = 0; v < points_.size(); ++v) {
      if (!alive_[v] || done[loop_of_[v]]) {
        continue;
      }
      done[loop_of_[v]] = true;
      Polyline& loop = loops[loop_of_[v]];
      std::uint32_t u = v;
      do {
        loop.push_back(points_[u]);
        u = next_[u];
      } while (u != v);
    }
    return loops;
  }

 private:
  [[nodiscard]] CGAL::Bbox_3 segment_box(std::uint32_t u) const {
    return points_[u].bbox() + points_[next_[u]].bbox();
  }

  // One sweep over all vertices; returns whether any vertex was deleted. A vertex next to a
  // segment created in this sweep waits for the next sweep, which bounds how far new segments
  // grow before the grid is rebuilt around the shorter segments.
  bool pass() {
    CGAL::Bbox_3 domain;
    double total_length = 0.0;
    std::size_t segments = 0;
    for (std::uint32_t u = 0; u < points_.size(); ++u) {
      if (alive_[u]) {
        domain += points_[u].bbox();
        total_length += std::sqrt(CGAL::squared_distance(points_[u], points_[next_[u]]));
        ++segments;
      }
    }
    if (segments == 0) {
      return false;
    }
    grid_ = SegmentGrid(domain, 2.0 * total_length / static_cast<double>(segments),
                        4 * segments + 64);
    for (std::uint32_t u = 0; u < points_.size(); ++u) {
      if (alive_[u]) {
        grid_.insert(u, segment_box(u));
      }
    }
    std::fill(changed_.begin(), changed_.end(), false);
    bool removed_any = false;
    for (std::uint32_t b = 0; b < points_.size(); ++b) {
      if (!alive_[b] || loop_size_[loop_of_[b]] <= 3) {
        continue;
      }
      const std::uint32_t a = prev_[b];
      if (changed_[a] || changed_[b] || !removable(b)) {
        continue;
      }
      const std::uint32_t c = next_[b];
      alive_[b] = false;
      next_[a] = c;
      prev_[c] = a;
      changed_[a] = true;
      --loop_size_[loop_of_[b]];
      grid_.insert(a, segment_box(a));
      removed_any = true;
    }
    return removed_any;
  }

  [[nodiscard]] bool removable(std::uint32_t b) {
    const std::uint32_t a = prev_[b];
    const std::uint32_t c = next_[b];
    const std::uint32_t p = prev_[a];
    const std::uint32_t q = next_[c];
    const Point3& pa = points_[a];
    const Point3& pb = points_[b];
    const Point3& pc = points_[c];
    if (!CGAL::collinear(pa, pb, pc)) {
      if (adjacent_enters(pa, pb, pc, points_[p]) || adjacent_enters(pc, pb, pa, points_[q])) {
        return false;
      }
      const Triangle3 triangle(pa, pb, pc);
      return region_is_free(pa.bbox() + pb.bbox() + pc.bbox(), {p, a, b, c},
                            [&](const Segment3& s) { return CGAL::do_intersect(triangle, s); });
    }
    // b inside segment ac: deleting it does not move the curve at all.
    if (CGAL::collinear_are_strictly_ordered_along_line(pa, pb, pc)) {
      return true;
    }
    // A spike that folds back on itself; an exact return (a == c) would leave a zero-length
    // segment, so it stays.
    if (pa == pc) {
      return false;
    }
    const bool a_inside = CGAL::collinear_are_strictly_ordered_along_line(pb, pa, pc);
    const Segment3 hull = a_inside ? Segment3(pb, pc) : Segment3(pa, pb);
    if (CGAL::collinear(points_[p], pa, pb) &&
        (a_inside || !CGAL::collinear_are_strictly_ordered_along_line(points_[p], pa, pb))) {
      return false;
    }
    if (CGAL::collinear(points_[q], pc, pb) &&
        (!a_inside || !CGAL::collinear_are_strictly_ordered_along_line(points_[q], pc, pb))) {
      return false;
    }
    return region_is_free(hull.bbox(), {p, a, b, c},
                          [&](const Segment3& s) { return CGAL::do_intersect(hull, s); });
  }

  // True when no segment other than the excluded ones (named by start vertex) meets the region.
  template <typename Meets>
  bool region_is_free(const CGAL::Bbox_3& box, const std::array<std::uint32_t, 4>& excluded,
                      Meets&& meets) {
    ++query_;
    bool free = true;
    grid_.for_each_cell(box, [&](std::vector<std::uint32_t>& cell) {
      if (!free) {
        return;
      }
      for (const std::uint32_t u : cell) {
        if (stamp_[u] == query_ || !alive_[u]) {
          continue;
        }
        stamp_[u] = query_;
        if (std::find(excluded.begin(), excluded.end(), u) != excluded.end()) {
          continue;
        }
        if (!CGAL::do_overlap(box, segment_box(u))) {
          continue;
        }
        if (meets(Segment3(points_[u], points_[next_[u]]))) {
          free = false;
          return;
        }
      }
    });
    return free;
  }

  std::vector<Point3> points_;
  std::vector<std::uint32_t> next_;
  std::vector<std::uint32_t> prev_;
  std::vector<std::uint32_t> loop_of_;
  std::vector<std::uint32_t> loop_size_;
  std::vector<bool> alive_;
  std::vector<bool> changed_;
  std::vector<std::uint64_t> stamp_;
  std::uint64_t query_ = 0;
  SegmentGrid grid_{CGAL::Bbox_3(0, 0, 0, 0, 0, 0), 1.0, 1};
};

}  // namespace

std::vector<Polyline> simplify_loops(const std::vector<Polyline>& loops) {
  Simplifier simplifier(loops);
  simplifier.run();
  return simplifier.result();
}

}  // namespace envcrust::knots::detail
