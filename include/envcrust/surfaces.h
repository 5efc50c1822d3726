// Built-in parametric test surfaces (the paper's examples and more) with exact geometry.
#pragma once

#include "envcrust/types.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace envcrust::surfaces {

/// S(u,v) and its first and second partial derivatives at one parameter point.
struct SurfaceJet {
  Point3 position;
  Vector3 du, dv;         ///< S_u, S_v
  Vector3 duu, duv, dvv;  ///< second partials
};

/// Differential geometry at one point: unit normal and principal curvatures (k1 has the
/// larger absolute value). Curvature signs follow `normal`; the normal is a line for
/// non-orientable surfaces.
struct SurfacePoint {
  Point3 position;
  Vector3 normal;
  double k1 = 0, k2 = 0;
};

/// How an edge pair of the parameter rectangle is identified.
enum class Gluing {
  None,            ///< both edges are boundary (or poles)
  Periodic,        ///< S(u1, v) = S(u0, v)
  PeriodicFlipped  ///< S(u1, v) = S(u0, v0 + v1 - v) (Moebius strip)
};

/// The parameter rectangle [u0,u1] x [v0,v1] and how its edges close up.
/// Only u may be PeriodicFlipped. A pole edge (v = v0 or v = v1) maps to a single point.
struct ParameterDomain {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  Gluing u_gluing = Gluing::None;
  Gluing v_gluing = Gluing::None;  ///< None or Periodic
  bool v0_is_pole = false;
  bool v1_is_pole = false;
};

/// The topology a correct reconstruction of the surface must have.
struct ExpectedTopology {
  int euler_characteristic = 0;
  int boundary_loops = 0;
  bool is_orientable = true;
  std::vector<std::string> boundary_knots;  ///< knot name per loop ("unknot", "trefoil")
  int abs_linking_number = 0;               ///< |lk| of loops 0 and 1 (0 when < 2 loops)
};

/// A parametric surface. Implementations give the exact jet; the rest derives from it.
class Surface {
 public:
  virtual ~Surface() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual std::string description() const = 0;
  [[nodiscard]] virtual ParameterDomain domain() const = 0;
  [[nodiscard]] virtual SurfaceJet evaluate(double u, double v) const = 0;
  [[nodiscard]] virtual ExpectedTopology expected_topology() const = 0;

  /// A trimmed surface: the closed loops of the parameter plane (first point not repeated)
  /// that bound the kept region, its boundary; empty (the default) for a surface that is its
  /// whole parameter domain, whose boundary is the domain's unglued edges.
  [[nodiscard]] virtual std::vector<std::vector<std::array<double, 2>>> trim_loops() const { return {}; }
  /// Whether (u, v) lies in the kept region (always, without trim loops).
  [[nodiscard]] virtual bool contains(double /*u*/, double /*v*/) const { return true; }

  /// Unit normal and principal curvatures from the jet (eigenvalues of I^-1 II).
  /// At a pole the limit is taken by evaluating slightly inside the domain.
  [[nodiscard]] SurfacePoint point_at(double u, double v) const;
};

/// Boundary curves are the shared envcrust types (types.h); these aliases keep the names.
using envcrust::BoundaryCurve;
using envcrust::BoundaryVertex;

/// Names of all built-in surfaces, in a stable order.
std::vector<std::string> builtin_names();

/// Make a built-in surface by name ("cylinder", "cylinder-nurbs", "paraboloid", "horn",
/// "cusp", "trefoil-ribbon", "unknot-ribbon", "moebius", "hemisphere", "square", "saddle",
/// "sphere", "torus"). @throws InvalidInput "unknown surface 'x' (known: a, b, ...)".
std::unique_ptr<Surface> make_builtin(std::string_view name);

/// Options of sample_surface.
struct SampleOptions {
  std::size_t count = 10000;     ///< number of points, >= 1
  double noise_rel_diag = 0.0;   ///< Gaussian noise sigma as a fraction of the bbox diagonal, in [0, 1]
  bool with_normals = false;     ///< fill PointSet::normals with the exact unit normals
  std::uint64_t seed = 1;        ///< same seed, same points
};

/// Draw points uniformly by surface area (rejection sampling on the exact area element
/// |S_u x S_v|, over the kept region of a trimmed surface), deterministic for a seed.
/// @throws InvalidOptions on count 0 or negative noise.
PointSet sample_surface(const Surface& surface, const SampleOptions& options = {});

/// Move each point by Gaussian noise of standard deviation `sigma` along each axis, from a
/// stream of its own for `seed` (sample_surface's noise).
void add_noise(std::vector<Point3>& points, double sigma, std::uint64_t seed);

/// Options of tessellate.
struct TessellationOptions {
  double max_error_rel_diag = 1e-4;  ///< bound on the chord error, fraction of the bbox diagonal
  std::optional<int> nu, nv;         ///< force grid resolution (quads along u and v)
  /// The bound in model units instead (set: max_error_rel_diag is not used, and the fine grid
  /// bbox_diagonal evaluates is saved: 66,000 evaluations, most of the time of a small patch).
  std::optional<double> max_error;
};

/// An exact, fine tessellation (ground truth): a grid in parameter space with glued edges
/// welded and poles collapsed, so the mesh has the surface's topology (a trimmed surface: the
/// grid's nodes in the kept region and its trim loops, constrained-Delaunay triangulated in
/// the parameter plane). Triangles are consistently oriented when the surface is orientable.
TriangleMesh tessellate(const Surface& surface, const TessellationOptions& options = {});

/// The boundary loops of the surface, each sampled so that consecutive vertices are at most
/// `max_spacing` apart (arc length). Glued edges are joined (the Moebius strip has one loop);
/// a trimmed surface's loops are its trim loops.
std::vector<BoundaryCurve> boundary_curves(const Surface& surface, double max_spacing);

/// Set `expected`'s boundary_loops, boundary_knots (the knot type of each loop's polyline;
/// "untyped" for a loop that touches itself or another: no generic projection) and
/// abs_linking_number (of loops 0 and 1) from the loops.
void set_boundary_loops(const std::vector<Polyline>& loops, ExpectedTopology& expected);

/// Bounding-box diagonal of the surface (from a fine parameter grid).
double bbox_diagonal(const Surface& surface);

/// Total area (numerical quadrature of |S_u x S_v|, relative error < 1e-6; over the kept region of a
/// trimmed surface, where the quadrature nodes inside count, much coarser).
double area(const Surface& surface);

}  // namespace envcrust::surfaces
