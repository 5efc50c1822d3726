// Boundary loops of a surface: unglued, non-pole domain edges traced into closed loops and
// resampled by arc length, with tangent, normal and outward conormal.
#include "builtin.h"
#include "vector_ops.h"

#include "envcrust/errors.h"
#include "envcrust/knots.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace envcrust::surfaces {

namespace {

constexpr std::size_t min_fine_steps = 4096;
constexpr std::size_t fine_steps_per_output = 8;

/// A straight piece of the parameter rectangle's boundary, traversed from start to end, with
/// the domain's outward normal (ou, ov).
struct Segment {
  double u_start, v_start, u_end, v_end;
  double ou, ov;
};

using Loop = std::vector<Segment>;

/// The loops in traversal order; in the plain rectangle every segment start is a corner.
std::vector<Loop> trace_loops(const ParameterDomain& d, bool& has_corners) {
  const Segment bottom{d.u0, d.v0, d.u1, d.v0, 0, -1};
  const Segment right{d.u1, d.v0, d.u1, d.v1, 1, 0};
  const Segment top{d.u1, d.v1, d.u0, d.v1, 0, 1};
  const Segment left{d.u0, d.v1, d.u0, d.v0, -1, 0};
  const bool v_glued = d.v_gluing == Gluing::Periodic;
  const bool has_bottom = !v_glued && !d.v0_is_pole;
  const bool has_top = !v_glued && !d.v1_is_pole;
  has_corners = false;
  std::vector<Loop> loops;
  switch (d.u_gluing) {
    case Gluing::Periodic:
      if (has_bottom) loops.push_back({bottom});
      if (has_top) loops.push_back({top});
      break;
    case Gluing::PeriodicFlipped:
      // (u1, v0) is glued to (u0, v1): the bottom edge runs on into the top edge, traversed
      // in the same u direction, and returns to (u0, v0) = (u1, v1).
      if (has_bottom && has_top) {
        loops.push_back({bottom, Segment{d.u0, d.v1, d.u1, d.v1, 0, 1}});
      }
      break;
    case Gluing::None:
      if (v_glued) {
        loops.push_back({right});
        loops.push_back({left});
      } else {
        Loop loop;
        if (has_bottom) loop.push_back(bottom);
        loop.push_back(right);
        if (has_top) loop.push_back(top);
        loop.push_back(left);
        has_corners = true;
        loops.push_back(loop);
      }
      break;
  }
  return loops;
}

BoundaryFrame frame_at(const Surface& surface, const Segment& s, double t) {
  const double u = s.u_start + t * (s.u_end - s.u_start);
  const double v = s.v_start + t * (s.v_end - s.v_start);
  const SurfaceJet jet = surface.evaluate(u, v);
  BoundaryFrame f;
  f.position = jet.position;
  f.tangent = normalized((s.u_end - s.u_start) * jet.du + (s.v_end - s.v_start) * jet.dv);
  f.normal = unit_normal_at(surface, u, v);
  // Push-forward of the domain's outward normal, made orthogonal to t and n.
  Vector3 c = s.ou * jet.du + s.ov * jet.dv;
  c = c - dot(c, f.tangent) * f.tangent;
  c = c - dot(c, f.normal) * f.normal;
  f.conormal = normalized(c);
  return f;
}

/// Parameters t in [0, 1) of points at equal arc length along the segment, at most `spacing`
/// apart.
std::vector<double> arc_length_parameters(const Surface& surface, const Segment& s,
                                          double spacing) {
  std::size_t steps = min_fine_steps;
  for (;;) {
    std::vector<Point3> fine;
    fine.reserve(steps + 1);
    for (std::size_t k = 0; k <= steps; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(steps);
      fine.push_back(surface
                         .evaluate(s.u_start + t * (s.u_end - s.u_start),
                                   s.v_start + t * (s.v_end - s.v_start))
                         .position);
    }
    std::vector<double> cumulative(steps + 1, 0.0);
    for (std::size_t k = 1; k <= steps; ++k) {
      cumulative[k] = cumulative[k - 1] + std::sqrt(CGAL::squared_distance(fine[k - 1], fine[k]));
    }
    const double length = cumulative.back();
    // The fine polyline is shorter than the curve by O(h^2): Richardson extrapolation against
    // the polyline through every other point (steps is even) estimates the true arc length.
    double coarse = 0;
    for (std::size_t k = 2; k <= steps; k += 2) {
      coarse += std::sqrt(CGAL::squared_distance(fine[k - 2], fine[k]));
    }
    const double arc = length + std::max(0.0, length - coarse) / 3;
    const auto count =
        static_cast<std::size_t>(std::max(1.0, std::ceil(arc / spacing * (1 - 1e-12))));
    if (count * fine_steps_per_output > steps) {
      steps = count * fine_steps_per_output;
      continue;
    }
    std::vector<double> params;
    params.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
      const double target = length * static_cast<double>(k) / static_cast<double>(count);
      const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), target);
      const auto hi =
          static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - cumulative.begin()));
      const double piece = cumulative[hi] - cumulative[hi - 1];
      const double fraction = piece > 0 ? (target - cumulative[hi - 1]) / piece : 0.0;
      params.push_back((static_cast<double>(hi - 1) + fraction) / static_cast<double>(steps));
    }
    return params;
  }
}

std::string format_value(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

std::vector<BoundaryCurve> boundary_curves(const Surface& surface, double max_spacing) {
  if (!(max_spacing > 0) || !std::isfinite(max_spacing)) {
    throw InvalidOptions("boundary spacing must be > 0 (got " + format_value(max_spacing) + ")");
  }
  if (!surface.trim_loops().empty()) return trim_boundary_curves(surface, max_spacing);
  bool has_corners = false;
  const std::vector<Loop> loops = trace_loops(surface.domain(), has_corners);
  std::vector<BoundaryCurve> curves;
  curves.reserve(loops.size());
  for (const Loop& loop : loops) {
    BoundaryCurve curve;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Segment& segment = loop[k];
      const std::vector<double> params = arc_length_parameters(surface, segment, max_spacing);
      for (std::size_t q = 0; q < params.size(); ++q) {
        const BoundaryFrame f = frame_at(surface, segment, params[q]);
        if (has_corners && q == 0 && loop.size() > 1) {
          const BoundaryFrame incoming = frame_at(surface, loop[(k + loop.size() - 1) % loop.size()], 1.0);
          curve.vertices.push_back(boundary_vertex(f, &incoming));
        } else {
          curve.vertices.push_back(boundary_vertex(f));
        }
      }
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

void set_boundary_loops(const std::vector<Polyline>& loops, ExpectedTopology& expected) {
  expected.boundary_loops = static_cast<int>(loops.size());
  expected.boundary_knots.clear();
  expected.abs_linking_number = 0;
  for (const auto& loop : loops) {
    try {
      expected.boundary_knots.push_back(knots::to_string(knots::identify_knot(loop).type));
    } catch (const NumericalFailure&) {
      expected.boundary_knots.push_back("untyped");
    }
  }
  try {
    if (loops.size() >= 2) expected.abs_linking_number = std::abs(knots::linking_number(loops[0], loops[1]));
  } catch (const NumericalFailure&) {
  }
}

}  // namespace envcrust::surfaces
