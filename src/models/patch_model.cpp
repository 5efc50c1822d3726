// A model of one or more patches: its ground truth, expected topology, boundary and samples.
#include "envcrust/models.h"

#include "model_boundary.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/topology.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>

namespace envcrust::models {
namespace {

std::string where(const Point3& p) {
  std::ostringstream s;
  s << std::setprecision(3) << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// Refuse a joined tessellation that is no surface, naming where.
void check_surface(const TriangleMesh& mesh, const topology::MeshTopology& topology) {
  if (topology.non_manifold_edges > 0) {
    std::map<std::pair<Index, Index>, int> faces_of_edge;
    for (const auto& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        const Index a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
        ++faces_of_edge[{std::min(a, b), std::max(a, b)}];
      }
    for (const auto& [edge, count] : faces_of_edge)
      if (count > 2)
        throw InvalidInput(std::to_string(count) + " patches meet along an edge near " +
                           where(CGAL::midpoint(mesh.vertices[edge.first], mesh.vertices[edge.second])) +
                           " (" + std::to_string(topology.non_manifold_edges) + " such edges): the patches form no surface");
  }
  if (topology.non_manifold_vertices > 0)
    throw InvalidInput("patches touch at " + std::to_string(topology.non_manifold_vertices) +
                       " points only (a vertex whose faces form several fans): the patches form no surface");
}

// The patches' tessellations stay this close to them, in fractions of the smaller of the
// patch's and the model's diagonal (tessellate's default, 1e-4 of the patch's own).
constexpr double kChordErrorRelDiag = 1e-4;

// Points of the patch on a 33 x 33 parameter grid, those in its kept region (all of them if
// none is): a coarse extent, for the tessellations' error bound.
std::vector<Point3> coarse_points(const surfaces::Surface& patch) {
  constexpr int n = 32;
  const surfaces::ParameterDomain d = patch.domain();
  std::vector<Point3> kept, all;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double u = d.u0 + (d.u1 - d.u0) * i / n, v = d.v0 + (d.v1 - d.v0) * j / n;
      const Point3 p = patch.evaluate(u, v).position;
      all.push_back(p);
      if (patch.contains(u, v)) kept.push_back(p);
    }
  }
  return kept.size() >= 2 ? kept : all;
}

}  // namespace

PatchModel::PatchModel(std::vector<std::unique_ptr<surfaces::Surface>> patches, std::string name,
                       const JoinOptions& options)
    : patches_(std::move(patches)), name_(std::move(name)) {
  if (patches_.empty()) throw InvalidInput(name_ + ": no patch");
  joins_.patches = patches_.size();
  if (patches_.size() == 1) {
    truth_ = surfaces::tessellate(*patches_.front());
    expected_ = patches_.front()->expected_topology();
    diagonal_ = surfaces::bbox_diagonal(*patches_.front());
    return;
  }
  // Each patch within 1e-4 of the smaller of its diagonal and the model's (coarse estimates),
  // so within the joining tolerance.
  std::vector<double> patch_diagonals;
  std::vector<Point3> coarse;
  for (const auto& p : patches_) {
    const auto points = coarse_points(*p);
    patch_diagonals.push_back(mesh::bbox_diagonal(points));
    coarse.insert(coarse.end(), points.begin(), points.end());
  }
  const double coarse_diagonal = mesh::bbox_diagonal(coarse);
  std::vector<TriangleMesh> parts;
  std::vector<Point3> all;
  for (std::size_t i = 0; i < patches_.size(); ++i) {
    const auto& p = patches_[i];
    surfaces::TessellationOptions o;
    o.max_error = kChordErrorRelDiag * std::min(patch_diagonals[i], coarse_diagonal);
    parts.push_back(surfaces::tessellate(*p, o));
    areas_.push_back(mesh::total_area(parts.back()));
    all.insert(all.end(), parts.back().vertices.begin(), parts.back().vertices.end());
  }
  diagonal_ = mesh::bbox_diagonal(all);
  JoinedMesh joined = join_tessellations(parts, options.tolerance_rel_diag * diagonal_);
  truth_ = std::move(joined.mesh);
  joins_ = joined.stats;
  const auto topology = topology::analyze_topology(truth_);
  check_surface(truth_, topology);
  topology::orient_faces(truth_);  // the patches' windings may disagree
  expected_.euler_characteristic = static_cast<int>(topology.euler_characteristic);
  expected_.is_orientable = topology.is_orientable;
  genus_ = topology::total_genus(topology);
  std::vector<Polyline> loops;
  for (const auto& loop : topology.boundary_loops) loops.push_back(loop.polyline(topology.points));
  surfaces::set_boundary_loops(loops, expected_);
}

PatchModel::~PatchModel() = default;
PatchModel::PatchModel(PatchModel&&) noexcept = default;
PatchModel& PatchModel::operator=(PatchModel&&) noexcept = default;

std::string PatchModel::description() const {
  if (patches_.size() == 1) return patches_.front()->description();
  std::ostringstream s;
  s << std::setprecision(3) << patches_.size() << " patches joined along " << joins_.joined_edges
    << " edges of their tessellations (largest gap " << joins_.largest_gap << ", tolerance " << joins_.tolerance << ")";
  if (joins_.near_misses > 0)
    s << "; " << joins_.near_misses << " border vertices left open lie " << joins_.nearest_miss
      << " or more from another patch's border, within 20 times the tolerance (a larger one joins them)";
  return s.str();
}

std::vector<BoundaryCurve> PatchModel::boundary_curves(double max_spacing) const {
  if (patches_.size() == 1) return surfaces::boundary_curves(*patches_.front(), max_spacing);
  if (expected_.boundary_loops == 0) return {};
  std::vector<std::vector<BoundaryCurve>> patch_curves;
  for (const auto& p : patches_) patch_curves.push_back(surfaces::boundary_curves(*p, max_spacing));
  return model_boundary_curves(truth_, patch_curves, joins_.tolerance);
}

PointSet PatchModel::sample(const surfaces::SampleOptions& options) const {
  if (patches_.size() == 1) return surfaces::sample_surface(*patches_.front(), options);
  if (!(options.noise_rel_diag >= 0 && options.noise_rel_diag <= 1))
    throw InvalidOptions("noise must be in [0, 1], a fraction of the diagonal (got " +
                         std::to_string(options.noise_rel_diag) + ")");
  // Counts in proportion to the patches' areas (their tessellations'), the remainders
  // handed out largest first.
  const double total = std::accumulate(areas_.begin(), areas_.end(), 0.0);
  std::vector<std::size_t> counts(patches_.size());
  std::vector<std::pair<double, std::size_t>> remainders;
  std::size_t given = 0;
  for (std::size_t i = 0; i < patches_.size(); ++i) {
    const double share = static_cast<double>(options.count) * areas_[i] / total;
    counts[i] = static_cast<std::size_t>(std::floor(share));
    given += counts[i];
    remainders.emplace_back(share - std::floor(share), i);
  }
  std::stable_sort(remainders.begin(), remainders.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; given < options.count; ++k, ++given) ++counts[remainders[k % remainders.size()].second];
  // A stream per patch, so the patches are sampled in parallel and the result is a function of
  // the seed (each patch's sampling bounds its area element on a fine grid first: most of the
  // time for small counts, 10 ms a patch).
  std::vector<PointSet> parts(patches_.size());
  tbb::parallel_for(std::size_t{0}, patches_.size(), [&](std::size_t i) {
    if (counts[i] == 0) return;
    surfaces::SampleOptions o = options;
    o.count = counts[i];
    o.noise_rel_diag = 0;
    o.seed = options.seed * 1000003 + i;
    parts[i] = surfaces::sample_surface(*patches_[i], o);
  });
  PointSet out;
  for (const auto& part : parts) {
    out.points.insert(out.points.end(), part.points.begin(), part.points.end());
    out.normals.insert(out.normals.end(), part.normals.begin(), part.normals.end());
  }
  if (options.noise_rel_diag > 0) surfaces::add_noise(out.points, options.noise_rel_diag * diagonal_, options.seed);
  return out;
}

}  // namespace envcrust::models
