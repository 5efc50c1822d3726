// Ground-truth triangle meshes: a welded parameter grid refined until the chord error is small.
#include "builtin.h"
#include "vector_ops.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace envcrust::surfaces {

namespace {

constexpr double max_triangles = 500000;
constexpr int estimate_grid = 64;
constexpr int max_refinements = 8;

struct Resolution {
  int nu = 1, nv = 1;
};

/// Fewest quads that keep the welded mesh free of duplicate edges and degenerate triangles.
Resolution minimum_resolution(const ParameterDomain& d) {
  Resolution r;
  r.nu = d.u_gluing == Gluing::None ? 1 : 3;
  r.nv = d.v_gluing == Gluing::Periodic ? 3 : 1;
  if (d.v0_is_pole && d.v1_is_pole) r.nv = std::max(r.nv, 2);
  if (d.v0_is_pole || d.v1_is_pole) r.nu = std::max(r.nu, 3);
  return r;
}

double parameter(double lo, double hi, int i, int n) { return lo + (hi - lo) * i / n; }

/// Bounds on |II| components at cell centres: the chord error of a step (hu, hv) is about
/// (L hu^2 + 2 M hu hv + N hv^2) / 8.
Resolution initial_resolution(const Surface& surface, const ParameterDomain& d, double tol) {
  double l_max = 0, m_max = 0, n_max = 0;
  for (int i = 0; i < estimate_grid; ++i) {
    const double u = parameter(d.u0, d.u1, 2 * i + 1, 2 * estimate_grid);
    for (int j = 0; j < estimate_grid; ++j) {
      const double v = parameter(d.v0, d.v1, 2 * j + 1, 2 * estimate_grid);
      const SurfaceJet jet = surface.evaluate(u, v);
      const Vector3 n = normalized(cross(jet.du, jet.dv));
      l_max = std::max(l_max, std::abs(dot(jet.duu, n)));
      m_max = std::max(m_max, std::abs(dot(jet.duv, n)));
      n_max = std::max(n_max, std::abs(dot(jet.dvv, n)));
    }
  }
  // Each direction alone uses half the budget; the twist term is then checked separately.
  double hu = l_max > 0 ? std::sqrt(4 * tol / l_max) : d.u1 - d.u0;
  double hv = n_max > 0 ? std::sqrt(4 * tol / n_max) : d.v1 - d.v0;
  hu = std::min(hu, d.u1 - d.u0);
  hv = std::min(hv, d.v1 - d.v0);
  const double total = (l_max * hu * hu + 2 * m_max * hu * hv + n_max * hv * hv) / 8;
  if (total > tol) {
    const double shrink = std::sqrt(tol / total);
    hu *= shrink;
    hv *= shrink;
  }
  return {static_cast<int>(std::ceil((d.u1 - d.u0) / hu - 1e-9)),
          static_cast<int>(std::ceil((d.v1 - d.v0) / hv - 1e-9))};
}

/// Normal distance between the chord midpoint of p, q and the surface point at the parameter
/// midpoint.
double chord_error(const Surface& surface, const Point3& p, const Point3& q, double u, double v) {
  const SurfaceJet jet = surface.evaluate(u, v);
  Vector3 n = normalized(cross(jet.du, jet.dv));
  if (dot(n, n) == 0) n = unit_normal_at(surface, u, v);
  const Point3 mid = CGAL::midpoint(p, q);
  return std::abs(dot(mid - jet.position, n));
}

/// Distance between the chord midpoint of p, q and the surface point at the parameter
/// midpoint: for edges along the boundary, where a curve that bends within the tangent plane
/// (a flat disc's rim) has no normal error but is cut short all the same.
double chord_gap(const Surface& surface, const Point3& p, const Point3& q, double u, double v) {
  return std::sqrt(CGAL::squared_distance(CGAL::midpoint(p, q), surface.evaluate(u, v).position));
}

struct GridErrors {
  double along_u = 0, along_v = 0, diagonal = 0;
};

GridErrors measure_errors(const Surface& surface, const ParameterDomain& d, Resolution r,
                          const std::vector<Point3>& grid) {
  const auto at = [&](int i, int j) {
    return grid[static_cast<std::size_t>(i) * static_cast<std::size_t>(r.nv + 1) +
                static_cast<std::size_t>(j)];
  };
  // Rows and columns on an unglued edge of the domain are boundary curves.
  const bool v_border = d.v_gluing == Gluing::None, u_border = d.u_gluing == Gluing::None;
  GridErrors e;
  for (int i = 0; i <= r.nu; ++i) {
    const double u = parameter(d.u0, d.u1, i, r.nu);
    const double u_mid = parameter(d.u0, d.u1, 2 * i + 1, 2 * r.nu);
    const bool border_column = u_border && (i == 0 || i == r.nu);
    for (int j = 0; j <= r.nv; ++j) {
      const double v = parameter(d.v0, d.v1, j, r.nv);
      const bool pole_row = (j == 0 && d.v0_is_pole) || (j == r.nv && d.v1_is_pole);
      const bool border_row = v_border && (j == 0 || j == r.nv);
      if (!pole_row && i < r.nu) {
        const double along = border_row ? chord_gap(surface, at(i, j), at(i + 1, j), u_mid, v)
                                        : chord_error(surface, at(i, j), at(i + 1, j), u_mid, v);
        e.along_u = std::max(e.along_u, along);
      }
      if (j == r.nv) continue;
      const double v_mid = parameter(d.v0, d.v1, 2 * j + 1, 2 * r.nv);
      if (i < r.nu || border_column) {
        const double along = border_column ? chord_gap(surface, at(i, j), at(i, j + 1), u, v_mid)
                                           : chord_error(surface, at(i, j), at(i, j + 1), u, v_mid);
        e.along_v = std::max(e.along_v, along);
      }
      if (i < r.nu)
        e.diagonal = std::max(e.diagonal, chord_error(surface, at(i, j), at(i + 1, j + 1), u_mid, v_mid));
    }
  }
  return e;
}

std::vector<Point3> grid_points(const Surface& surface, const ParameterDomain& d, Resolution r) {
  std::vector<Point3> grid;
  grid.reserve(static_cast<std::size_t>(r.nu + 1) * static_cast<std::size_t>(r.nv + 1));
  for (int i = 0; i <= r.nu; ++i) {
    for (int j = 0; j <= r.nv; ++j) {
      grid.push_back(
          surface.evaluate(parameter(d.u0, d.u1, i, r.nu), parameter(d.v0, d.v1, j, r.nv))
              .position);
    }
  }
  return grid;
}

double triangle_count(Resolution r) { return 2.0 * r.nu * r.nv; }

/// Grid fine enough for the error bound, refined where measured errors exceed it.
Resolution choose_resolution(const Surface& surface, const ParameterDomain& d, double tol,
                             Resolution minimum) {
  Resolution r = initial_resolution(surface, d, tol);
  const auto clamp_to_limits = [&](Resolution& res) {
    res.nu = std::max(res.nu, minimum.nu);
    res.nv = std::max(res.nv, minimum.nv);
    if (triangle_count(res) > max_triangles) {
      const double scale = std::sqrt(max_triangles / triangle_count(res));
      res.nu = std::max(minimum.nu, static_cast<int>(res.nu * scale));
      res.nv = std::max(minimum.nv, static_cast<int>(res.nv * scale));
    }
  };
  clamp_to_limits(r);
  for (int round = 0; round < max_refinements; ++round) {
    const GridErrors e = measure_errors(surface, d, r, grid_points(surface, d, r));
    if (std::max({e.along_u, e.along_v, e.diagonal}) <= tol) break;
    // Chord error scales with the square of the step (h^1.5 at the cusp's apex: the margin
    // covers it over a few rounds).
    const auto factor = [&](double err) { return std::sqrt(err / tol) * 1.1; };
    Resolution next = r;
    const double diag_factor = e.diagonal > tol ? factor(e.diagonal) : 1.0;
    const double fu = std::max(e.along_u > tol ? factor(e.along_u) : 1.0, diag_factor);
    const double fv = std::max(e.along_v > tol ? factor(e.along_v) : 1.0, diag_factor);
    next.nu = static_cast<int>(std::ceil(r.nu * fu));
    next.nv = static_cast<int>(std::ceil(r.nv * fv));
    clamp_to_limits(next);
    if (next.nu == r.nu && next.nv == r.nv) break;  // at the triangle budget
    r = next;
  }
  return r;
}

std::string format_value(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

TriangleMesh tessellate(const Surface& surface, const TessellationOptions& options) {
  const ParameterDomain d = surface.domain();
  const Resolution minimum = minimum_resolution(d);
  if (options.nu && *options.nu < minimum.nu) {
    throw InvalidOptions("nu must be >= " + std::to_string(minimum.nu) + " for '" + surface.name() +
                         "' (got " + std::to_string(*options.nu) + ")");
  }
  if (options.nv && *options.nv < minimum.nv) {
    throw InvalidOptions("nv must be >= " + std::to_string(minimum.nv) + " for '" + surface.name() +
                         "' (got " + std::to_string(*options.nv) + ")");
  }
  Resolution r;
  if (options.nu && options.nv) {
    r = {*options.nu, *options.nv};
  } else {
    if (options.max_error && (!(*options.max_error > 0) || !std::isfinite(*options.max_error)))
      throw InvalidOptions("max_error must be > 0 (got " + format_value(*options.max_error) + ")");
    if (!options.max_error && (!(options.max_error_rel_diag > 0) || !std::isfinite(options.max_error_rel_diag))) {
      throw InvalidOptions("max_error_rel_diag must be > 0 (got " +
                           format_value(options.max_error_rel_diag) + ")");
    }
    const double tol = options.max_error ? *options.max_error : options.max_error_rel_diag * bbox_diagonal(surface);
    r = choose_resolution(surface, d, tol, minimum);
    if (options.nu) r.nu = *options.nu;
    if (options.nv) r.nv = *options.nv;
  }

  if (!surface.trim_loops().empty()) return tessellate_trimmed(surface, r.nu, r.nv);

  // Welding: every grid node gets the id of its canonical node. Canonical nodes come first in
  // (i, j) order, so a glued node's canonical id already exists when it is reached.
  const auto columns = static_cast<std::size_t>(r.nv + 1);
  const auto node = [&](int i, int j) {
    return static_cast<std::size_t>(i) * columns + static_cast<std::size_t>(j);
  };
  constexpr Index unassigned = ~Index{0};
  std::vector<Index> ids(static_cast<std::size_t>(r.nu + 1) * columns, unassigned);
  Index pole0 = unassigned, pole1 = unassigned;
  TriangleMesh mesh;
  const auto new_vertex = [&](double u, double v) {
    mesh.vertices.push_back(surface.evaluate(u, v).position);
    return static_cast<Index>(mesh.vertices.size() - 1);
  };
  for (int i = 0; i <= r.nu; ++i) {
    for (int j = 0; j <= r.nv; ++j) {
      Index& id = ids[node(i, j)];
      if (j == 0 && d.v0_is_pole) {
        if (pole0 == unassigned) pole0 = new_vertex(d.u0, d.v0);
        id = pole0;
        continue;
      }
      if (j == r.nv && d.v1_is_pole) {
        if (pole1 == unassigned) pole1 = new_vertex(d.u0, d.v1);
        id = pole1;
        continue;
      }
      int ci = i, cj = j;
      if (i == r.nu && d.u_gluing != Gluing::None) {
        ci = 0;
        if (d.u_gluing == Gluing::PeriodicFlipped) cj = r.nv - j;
      }
      if (cj == r.nv && d.v_gluing == Gluing::Periodic) cj = 0;
      id = (ci == i && cj == j)
               ? new_vertex(parameter(d.u0, d.u1, i, r.nu), parameter(d.v0, d.v1, j, r.nv))
               : ids[node(ci, cj)];
    }
  }

  mesh.triangles.reserve(static_cast<std::size_t>(triangle_count(r)));
  const auto emit = [&](Index a, Index b, Index c) {
    if (a != b && b != c && a != c) mesh.triangles.push_back({a, b, c});
  };
  for (int i = 0; i < r.nu; ++i) {
    for (int j = 0; j < r.nv; ++j) {
      const Index a = ids[node(i, j)], b = ids[node(i + 1, j)];
      const Index c = ids[node(i + 1, j + 1)], e = ids[node(i, j + 1)];
      // Counter-clockwise in (u, v): the triangles' normals follow S_u x S_v.
      emit(a, b, c);
      emit(a, c, e);
    }
  }
  return mesh;
}

}  // namespace envcrust::surfaces
