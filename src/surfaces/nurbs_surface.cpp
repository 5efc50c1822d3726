// A NURBS patch read from a file as a Surface: exact jet, glued and collapsed edges found
// from the geometry, expected topology derived from the glued parameter rectangle.
#include "envcrust/nurbs_surface.h"

#include "builtin.h"
#include "bspline_basis.h"
#include "nurbs_curve.h"
#include "trim_region.h"
#include "vector_ops.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace envcrust::surfaces {

namespace {

/// Edge points closer than this fraction of the control net's diagonal count as one: loose
/// enough for a seam written with 6 significant digits, far below anything a reconstruction
/// resolves (rho is a few percent of the diagonal).
constexpr double kEdgeToleranceRelDiag = 1e-5;
/// Points compared along an edge to decide gluing and poles.
constexpr int kEdgeProbes = 33;
/// Cell centres checked for a vanishing or reversing S_u x S_v inside the patch.
constexpr int kRegularityGrid = 24;
/// A turn of the normal between neighbouring cells beyond this reads as a fold.
constexpr double kFoldDegrees = 120;

std::string number(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

void check_direction(const char* name, int degree, std::size_t count, const std::vector<double>& knots) {
  const std::string dir(name);
  if (degree < 1 || degree > max_bspline_degree)
    throw InvalidInput("NURBS surface: degree in " + dir + " must be 1 to " + std::to_string(max_bspline_degree) +
                       ", got " + std::to_string(degree));
  if (count < static_cast<std::size_t>(degree) + 1)
    throw InvalidInput("NURBS surface: " + std::to_string(count) + " control points along " + dir +
                       " are too few for degree " + std::to_string(degree) + " (need at least " +
                       std::to_string(degree + 1) + ")");
  if (knots.size() != count + static_cast<std::size_t>(degree) + 1)
    throw InvalidInput("NURBS surface: " + std::to_string(knots.size()) + " knots in " + dir + ", expected " +
                       std::to_string(count + static_cast<std::size_t>(degree) + 1) +
                       " (control points + degree + 1)");
  for (std::size_t k = 0; k < knots.size(); ++k) {
    if (!std::isfinite(knots[k])) throw InvalidInput("NURBS surface: knot " + std::to_string(k) + " in " + dir + " is not finite");
    if (k > 0 && knots[k] < knots[k - 1])
      throw InvalidInput("NURBS surface: knots in " + dir + " decrease at index " + std::to_string(k) + " (" +
                         number(knots[k - 1]) + " then " + number(knots[k]) + ")");
  }
  // Inside the valid range a knot repeated more than `degree` times breaks the surface apart.
  const double first = knots[static_cast<std::size_t>(degree)], last = knots[count];
  for (std::size_t k = 0; k < knots.size();) {
    std::size_t end = k;
    while (end < knots.size() && knots[end] == knots[k]) ++end;
    if (knots[k] > first && knots[k] < last && end - k > static_cast<std::size_t>(degree))
      throw InvalidInput("NURBS surface: knot " + number(knots[k]) + " in " + dir + " is repeated " +
                         std::to_string(end - k) + " times, more than the degree " + std::to_string(degree) +
                         ": the surface is torn apart there");
    k = end;
  }
}

void check_patch(const NurbsPatch& p) {
  check_direction("u", p.degree_u, p.count_u, p.knots_u);
  check_direction("v", p.degree_v, p.count_v, p.knots_v);
  const std::size_t total = p.count_u * p.count_v;
  if (p.control_points.size() != total || p.weights.size() != total)
    throw InvalidInput("NURBS surface: " + std::to_string(p.control_points.size()) + " control points and " +
                       std::to_string(p.weights.size()) + " weights, expected " + std::to_string(total) + " (" +
                       std::to_string(p.count_u) + " x " + std::to_string(p.count_v) + ")");
  for (std::size_t k = 0; k < total; ++k) {
    const std::string which =
        "control point (" + std::to_string(k % p.count_u) + ", " + std::to_string(k / p.count_u) + ")";
    const Point3& q = p.control_points[k];
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()))
      throw InvalidInput("NURBS surface: " + which + " is not finite");
    if (!(p.weights[k] > 0) || !std::isfinite(p.weights[k]))
      throw InvalidInput("NURBS surface: the weight of " + which + " is " + number(p.weights[k]) +
                         ", weights must be finite and > 0");
  }
}

/// The patch's own parameters and jet, before any exchange of u and v.
class RawPatch {
 public:
  explicit RawPatch(NurbsPatch patch) : p_(std::move(patch)) {
    check_patch(p_);
    range_ = {p_.knots_u[static_cast<std::size_t>(p_.degree_u)], p_.knots_u[p_.count_u],
              p_.knots_v[static_cast<std::size_t>(p_.degree_v)], p_.knots_v[p_.count_v]};
    if (p_.parameter_range) {
      const auto& r = *p_.parameter_range;
      if (!(r[0] < r[1]) || !(r[2] < r[3]) || r[0] < range_[0] - 1e-12 * std::abs(range_[1] - range_[0]) ||
          r[1] > range_[1] + 1e-12 * std::abs(range_[1] - range_[0]) ||
          r[2] < range_[2] - 1e-12 * std::abs(range_[3] - range_[2]) ||
          r[3] > range_[3] + 1e-12 * std::abs(range_[3] - range_[2]))
        throw InvalidInput("NURBS surface: parameter range [" + number(r[0]) + ", " + number(r[1]) + "] x [" +
                           number(r[2]) + ", " + number(r[3]) + "] is empty or outside the knots' [" +
                           number(range_[0]) + ", " + number(range_[1]) + "] x [" + number(range_[2]) + ", " +
                           number(range_[3]) + "]");
      range_ = {std::max(r[0], range_[0]), std::min(r[1], range_[1]), std::max(r[2], range_[2]),
                std::min(r[3], range_[3])};
    }
    if (!(range_[0] < range_[1]) || !(range_[2] < range_[3]))
      throw InvalidInput("NURBS surface: the knots leave an empty parameter range (first and last valid knots equal)");
  }

  [[nodiscard]] const std::array<double, 4>& range() const { return range_; }
  [[nodiscard]] const NurbsPatch& patch() const { return p_; }

  [[nodiscard]] SurfaceJet evaluate(double u, double v) const {
    u = std::clamp(u, range_[0], range_[1]);
    v = std::clamp(v, range_[2], range_[3]);
    const int su = find_knot_span(p_.knots_u, p_.degree_u, static_cast<int>(p_.count_u), u);
    const int sv = find_knot_span(p_.knots_v, p_.degree_v, static_cast<int>(p_.count_v), v);
    const BasisDerivatives nu = basis_derivatives(su, u, p_.degree_u, p_.knots_u);
    const BasisDerivatives nv = basis_derivatives(sv, v, p_.degree_v, p_.knots_v);
    // Homogeneous sums A = sum N M w P and w = sum N M w with their derivatives d^(a+b)/du^a dv^b.
    double a[3][3][3] = {};
    double w[3][3] = {};
    for (int j = 0; j <= p_.degree_v; ++j) {
      const auto jj = static_cast<std::size_t>(sv - p_.degree_v + j);
      const auto& mv = nv[static_cast<std::size_t>(j)];
      for (int i = 0; i <= p_.degree_u; ++i) {
        const auto ii = static_cast<std::size_t>(su - p_.degree_u + i);
        const auto& mu = nu[static_cast<std::size_t>(i)];
        const std::size_t index = ii + p_.count_u * jj;
        const double weight = p_.weights[index];
        const Point3& q = p_.control_points[index];
        for (int da = 0; da <= 2; ++da) {
          for (int db = 0; da + db <= 2; ++db) {
            const double b = mu[static_cast<std::size_t>(da)] * mv[static_cast<std::size_t>(db)] * weight;
            a[da][db][0] += b * q.x();
            a[da][db][1] += b * q.y();
            a[da][db][2] += b * q.z();
            w[da][db] += b;
          }
        }
      }
    }
    const auto vec = [&](int da, int db) { return Vector3(a[da][db][0], a[da][db][1], a[da][db][2]); };
    const double w0 = w[0][0];
    const Vector3 s = vec(0, 0) / w0;
    SurfaceJet jet;
    jet.position = Point3(s.x(), s.y(), s.z());
    jet.du = (vec(1, 0) - w[1][0] * s) / w0;
    jet.dv = (vec(0, 1) - w[0][1] * s) / w0;
    jet.duu = (vec(2, 0) - 2 * w[1][0] * jet.du - w[2][0] * s) / w0;
    jet.dvv = (vec(0, 2) - 2 * w[0][1] * jet.dv - w[0][2] * s) / w0;
    jet.duv = (vec(1, 1) - w[1][1] * s - w[1][0] * jet.dv - w[0][1] * jet.du) / w0;
    return jet;
  }

  [[nodiscard]] Point3 at(double u, double v) const { return evaluate(u, v).position; }

 private:
  NurbsPatch p_;
  std::array<double, 4> range_{};
};

double control_net_diagonal(const NurbsPatch& p) {
  const auto box = CGAL::bbox_3(p.control_points.begin(), p.control_points.end());
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

/// How the edges of the raw patch close up.
struct EdgeFacts {
  Gluing u = Gluing::None, v = Gluing::None;
  bool u0_pole = false, u1_pole = false, v0_pole = false, v1_pole = false;
};

EdgeFacts find_edges(const RawPatch& raw, double tolerance) {
  // Named copies, not a structured binding: Clang before 16 cannot capture bindings in lambdas.
  const double u0 = raw.range()[0], u1 = raw.range()[1], v0 = raw.range()[2], v1 = raw.range()[3];
  const auto t_of = [](double lo, double hi, int k) { return lo + (hi - lo) * k / (kEdgeProbes - 1); };
  const auto near = [&](const Point3& a, const Point3& b) { return CGAL::squared_distance(a, b) <= tolerance * tolerance; };
  const auto all = [&](auto predicate) {
    for (int k = 0; k < kEdgeProbes; ++k)
      if (!predicate(k)) return false;
    return true;
  };
  EdgeFacts f;
  // u-edges are the curves u = u0 and u = u1 (running along v), v-edges v = v0 and v = v1.
  if (all([&](int k) { return near(raw.at(u0, t_of(v0, v1, k)), raw.at(u1, t_of(v0, v1, k))); }))
    f.u = Gluing::Periodic;
  else if (all([&](int k) { return near(raw.at(u0, t_of(v0, v1, k)), raw.at(u1, t_of(v1, v0, k))); }))
    f.u = Gluing::PeriodicFlipped;
  if (all([&](int k) { return near(raw.at(t_of(u0, u1, k), v0), raw.at(t_of(u0, u1, k), v1)); }))
    f.v = Gluing::Periodic;
  else if (all([&](int k) { return near(raw.at(t_of(u0, u1, k), v0), raw.at(t_of(u1, u0, k), v1)); }))
    f.v = Gluing::PeriodicFlipped;
  f.u0_pole = all([&](int k) { return near(raw.at(u0, t_of(v0, v1, k)), raw.at(u0, v0)); });
  f.u1_pole = all([&](int k) { return near(raw.at(u1, t_of(v0, v1, k)), raw.at(u1, v0)); });
  f.v0_pole = all([&](int k) { return near(raw.at(t_of(u0, u1, k), v0), raw.at(u0, v0)); });
  f.v1_pole = all([&](int k) { return near(raw.at(t_of(u0, u1, k), v1), raw.at(u0, v1)); });
  // A pole edge "glued" to the opposite pole is a degenerate patch, not a gluing.
  if (f.u0_pole && f.u1_pole && f.u != Gluing::None) f.u = Gluing::None;
  if (f.v0_pole && f.v1_pole && f.v != Gluing::None) f.v = Gluing::None;
  return f;
}

/// Points per trimming curve: fine enough that the polyline's chord error is far below the
/// reconstruction's resolution (a quarter circle's: 2e-6 of its radius).
constexpr int kTrimCurvePoints = 512;

/// The trimming loops as closed parameter-plane polylines: each curve evaluated at
/// kTrimCurvePoints, turned to continue from the previous one's end, the chain checked to
/// close up within the domain and to bound an area.
std::vector<std::vector<Uv>> trim_polylines(const std::vector<std::vector<TrimCurve>>& loops,
                                            const std::array<double, 4>& range) {
  const double size = std::max(range[1] - range[0], range[3] - range[2]);
  const double gap = 1e-5 * size;
  std::vector<std::vector<Uv>> out;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::string which = "trim loop " + std::to_string(l);
    std::vector<Uv> polyline;
    for (std::size_t c = 0; c < loops[l].size(); ++c) {
      const TrimCurve& t = loops[l][c];
      std::vector<Eigen::Vector3d> points;
      for (const auto& [u, v] : t.points) points.emplace_back(u, v, 0.0);
      std::vector<Uv> curve;
      try {
        const RationalBSplineCurve spline(t.degree, points, t.weights, t.knots);
        const double a = spline.first_parameter(), b = spline.last_parameter();
        if (!(a < b)) throw InvalidInput("its knots leave an empty parameter range");
        const int steps = t.degree == 1 && t.points.size() == 2 ? 1 : kTrimCurvePoints;
        for (int k = 0; k <= steps; ++k) {
          const Eigen::Vector3d p = spline.evaluate(a + (b - a) * k / steps).position;
          curve.push_back({p.x(), p.y()});
        }
      } catch (const InvalidInput& e) {
        throw InvalidInput("NURBS surface: " + which + ", curve " + std::to_string(c) + ": " + e.what());
      }
      const auto distance = [](const Uv& p, const Uv& q) { return std::hypot(p[0] - q[0], p[1] - q[1]); };
      if (!polyline.empty()) {
        if (distance(polyline.back(), curve.back()) < distance(polyline.back(), curve.front()))
          std::reverse(curve.begin(), curve.end());
        if (distance(polyline.back(), curve.front()) > gap)
          throw InvalidInput("NURBS surface: " + which + " breaks between curves " + std::to_string(c - 1) + " and " +
                             std::to_string(c) + " (a gap of " + number(distance(polyline.back(), curve.front())) + ")");
        polyline.pop_back();  // the joint once
      } else if (loops[l].size() > 1) {
        // The first curve runs towards the second: turn it if its start is nearer to it.
        const auto& next = loops[l][1].points;
        const double to_start = std::min(distance(curve.front(), next.front()), distance(curve.front(), next.back()));
        const double to_end = std::min(distance(curve.back(), next.front()), distance(curve.back(), next.back()));
        if (to_start < to_end) std::reverse(curve.begin(), curve.end());
      }
      polyline.insert(polyline.end(), curve.begin(), curve.end());
    }
    if (polyline.size() < 4 || std::hypot(polyline.back()[0] - polyline.front()[0], polyline.back()[1] - polyline.front()[1]) > gap)
      throw InvalidInput("NURBS surface: " + which + " does not close up");
    polyline.pop_back();
    double area = 0;
    for (std::size_t k = 0; k < polyline.size(); ++k) {
      const Uv& p = polyline[k];
      const Uv& q = polyline[(k + 1) % polyline.size()];
      area += p[0] * q[1] - q[0] * p[1];
      if (p[0] < range[0] - gap || p[0] > range[1] + gap || p[1] < range[2] - gap || p[1] > range[3] + gap)
        throw InvalidInput("NURBS surface: " + which + " leaves the parameter domain at (" + number(p[0]) + ", " +
                           number(p[1]) + ")");
    }
    if (!(std::abs(area) / 2 > 1e-10 * size * size)) throw InvalidInput("NURBS surface: " + which + " bounds no area");
    for (auto& p : polyline) p = {std::clamp(p[0], range[0], range[1]), std::clamp(p[1], range[2], range[3])};
    out.push_back(std::move(polyline));
  }
  return out;
}

class NurbsSurface final : public Surface {
 public:
  NurbsSurface(NurbsPatch patch, std::string name) : raw_(std::move(patch)), name_(std::move(name)) {
    const double tolerance = kEdgeToleranceRelDiag * control_net_diagonal(raw_.patch());
    if (!(tolerance > 0)) throw InvalidInput("NURBS surface: all control points coincide");
    const EdgeFacts f = find_edges(raw_, tolerance);
    const bool u_poles = f.u0_pole || f.u1_pole;
    const bool v_poles = f.v0_pole || f.v1_pole;
    if (u_poles && v_poles)
      throw InvalidInput("NURBS surface: edges collapse to points in both parameter directions (a degenerate patch)");
    if (f.u != Gluing::None && f.v != Gluing::None && (f.u == Gluing::PeriodicFlipped || f.v == Gluing::PeriodicFlipped))
      throw InvalidInput("NURBS surface: its edges are glued into a Klein bottle, which cannot be embedded in space");
    // ParameterDomain wants poles on v-edges and a flipped gluing in u: exchange u and v when needed.
    swapped_ = u_poles || f.v == Gluing::PeriodicFlipped;
    const auto [u0, u1, v0, v1] = raw_.range();
    if (!swapped_) {
      domain_ = {.u0 = u0, .u1 = u1, .v0 = v0, .v1 = v1, .u_gluing = f.u, .v_gluing = f.v,
                 .v0_is_pole = f.v0_pole, .v1_is_pole = f.v1_pole};
    } else {
      domain_ = {.u0 = v0, .u1 = v1, .v0 = u0, .v1 = u1, .u_gluing = f.v, .v_gluing = f.u,
                 .v0_is_pole = f.u0_pole, .v1_is_pole = f.u1_pole};
    }
    const bool poles = domain_.v0_is_pole || domain_.v1_is_pole;
    if (poles && domain_.u_gluing == Gluing::PeriodicFlipped)
      throw InvalidInput("NURBS surface: an edge collapses to a point on a strip glued with a flip (a degenerate patch)");
    if (poles && domain_.v_gluing != Gluing::None)
      throw InvalidInput("NURBS surface: an edge collapses to a point although the patch closes up across it (a degenerate patch)");
    if (!raw_.patch().trim_loops.empty()) {
      if (poles || domain_.u_gluing != Gluing::None || domain_.v_gluing != Gluing::None)
        throw InvalidInput("NURBS surface: trimming a patch that closes up (a seam or an edge collapsed to a point) "
                           "is not supported");
      trim_ = TrimRegion(trim_polylines(raw_.patch().trim_loops, raw_.range()));
    }
    check_regular();
  }

  [[nodiscard]] std::vector<std::vector<std::array<double, 2>>> trim_loops() const override { return trim_.loops(); }
  [[nodiscard]] bool contains(double u, double v) const override { return trim_.contains(u, v); }

  [[nodiscard]] std::string name() const override { return name_; }
  [[nodiscard]] std::string description() const override {
    const NurbsPatch& p = raw_.patch();
    const bool rational = std::any_of(p.weights.begin(), p.weights.end(), [&](double w) { return w != p.weights[0]; });
    std::string text = std::string(rational ? "rational" : "polynomial") + " B-spline patch of degree " +
                       std::to_string(p.degree_u) + " x " + std::to_string(p.degree_v) + ", " +
                       std::to_string(p.count_u) + " x " + std::to_string(p.count_v) + " control points";
    const auto gluing = [](Gluing g, const char* dir) -> std::string {
      if (g == Gluing::Periodic) return std::string(", closed in ") + dir;
      if (g == Gluing::PeriodicFlipped) return std::string(", closed in ") + dir + " with a flip";
      return "";
    };
    const char* first = swapped_ ? "v" : "u";
    const char* second = swapped_ ? "u" : "v";
    text += gluing(domain_.u_gluing, first) + gluing(domain_.v_gluing, second);
    const int poles = int(domain_.v0_is_pole) + int(domain_.v1_is_pole);
    if (poles > 0) text += ", " + std::to_string(poles) + (poles == 1 ? " edge collapsed" : " edges collapsed") + " to a point";
    const std::size_t loops = trim_.loops().size();
    if (loops > 0) text += ", trimmed by " + std::to_string(loops) + (loops == 1 ? " loop" : " loops");
    return text;
  }
  [[nodiscard]] ParameterDomain domain() const override { return domain_; }
  [[nodiscard]] SurfaceJet evaluate(double u, double v) const override {
    if (!swapped_) return raw_.evaluate(u, v);
    const SurfaceJet raw = raw_.evaluate(v, u);
    return {raw.position, raw.dv, raw.du, raw.dvv, raw.duv, raw.duu};
  }
  [[nodiscard]] ExpectedTopology expected_topology() const override {
    ExpectedTopology t;
    const int poles = int(domain_.v0_is_pole) + int(domain_.v1_is_pole);
    t.is_orientable = domain_.u_gluing != Gluing::PeriodicFlipped;
    if (!trim_.empty()) {
      // Each loop inside an even number of others bounds a piece (a disc, +1), each one inside
      // an odd number a hole in it (-1).
      const auto& loops = trim_.loops();
      for (std::size_t a = 0; a < loops.size(); ++a) {
        int depth = 0;
        for (std::size_t b = 0; b < loops.size(); ++b)
          if (b != a && is_inside_loop(loops[b], loops[a][0][0], loops[a][0][1])) ++depth;
        t.euler_characteristic += depth % 2 == 0 ? 1 : -1;
      }
    } else if (domain_.u_gluing == Gluing::None && domain_.v_gluing == Gluing::None) {
      t.euler_characteristic = 1;  // a disc, whatever collapses
    } else if (domain_.u_gluing != Gluing::None && domain_.v_gluing != Gluing::None) {
      t.euler_characteristic = 0;  // a torus
    } else if (domain_.u_gluing == Gluing::PeriodicFlipped) {
      t.euler_characteristic = 0;  // a Moebius strip
    } else {
      t.euler_characteristic = poles;  // a tube, each collapsed end closing it: disc, sphere
    }
    const auto curves = boundary_curves(*this, 2e-3 * bbox_diagonal(*this));
    std::vector<Polyline> loops;
    for (const auto& c : curves) loops.push_back(c.polyline());
    set_boundary_loops(loops, t);
    return t;
  }

 private:
  /// Refuse a patch whose normal is undefined inside (a collapsed interior row) or that folds
  /// back on itself (the normal turns by more than kFoldDegrees between neighbouring cells).
  void check_regular() const {
    const ParameterDomain& d = domain_;
    const auto cell = [&](int i, int j) {
      return std::array<double, 2>{d.u0 + (d.u1 - d.u0) * (i + 0.5) / kRegularityGrid,
                                   d.v0 + (d.v1 - d.v0) * (j + 0.5) / kRegularityGrid};
    };
    std::vector<Vector3> normals;  // S_u x S_v per cell, i fastest
    double largest = 0;
    for (int j = 0; j < kRegularityGrid; ++j) {
      for (int i = 0; i < kRegularityGrid; ++i) {
        const auto [u, v] = cell(i, j);
        const SurfaceJet jet = evaluate(u, v);
        normals.push_back(cross(jet.du, jet.dv));
        largest = std::max(largest, norm(normals.back()));
      }
    }
    const auto where = [&](int i, int j) {
      const auto [u, v] = cell(i, j);
      return "(u, v) = (" + number(u) + ", " + number(v) + ")";
    };
    const double fold_cos = std::cos(kFoldDegrees * std::numbers::pi / 180);
    const auto kept = [&](int i, int j) {
      const auto [u, v] = cell(i, j);
      return contains(u, v);
    };
    for (int j = 0; j < kRegularityGrid; ++j) {
      for (int i = 0; i < kRegularityGrid; ++i) {
        const Vector3& n = normals[static_cast<std::size_t>(i + kRegularityGrid * j)];
        if (!kept(i, j)) continue;
        if (!(norm(n) > 1e-12 * largest))
          throw InvalidInput("NURBS surface: S_u x S_v vanishes inside the patch at " + where(i, j) +
                             ": its normal is undefined there");
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
          if (i + di >= kRegularityGrid || j + dj >= kRegularityGrid || !kept(i + di, j + dj)) continue;
          const Vector3& m = normals[static_cast<std::size_t>(i + di + kRegularityGrid * (j + dj))];
          if (dot(normalized(n), normalized(m)) < fold_cos)
            throw InvalidInput("NURBS surface: the patch folds back on itself between " + where(i, j) + " and " +
                               where(i + di, j + dj) + " (its normal turns by more than " +
                               number(kFoldDegrees) + " degrees)");
        }
      }
    }
  }

  RawPatch raw_;
  TrimRegion trim_;
  std::string name_;
  bool swapped_ = false;
  ParameterDomain domain_;
};

}  // namespace

std::unique_ptr<Surface> make_nurbs_surface(NurbsPatch patch, std::string name) {
  return std::make_unique<NurbsSurface>(std::move(patch), std::move(name));
}

}  // namespace envcrust::surfaces
