// remesh: validate, check the input can be remeshed, run CGAL, undo on a topology change.
#include "envcrust/remesh.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/topology.h"
#include "fitness.h"
#include "isotropic.h"

#include <CGAL/exceptions.h>

#include <chrono>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace envcrust::remesh {
namespace {

void validate(const RemeshOptions& o) {
  auto fail = [](const std::string& field, const std::string& range, double value) {
    std::ostringstream s;
    s << "RemeshOptions::" << field << " must be " << range << " (got " << value << ")";
    throw InvalidOptions(s.str());
  };
  if (o.target_edge_length && !(std::isfinite(*o.target_edge_length) && *o.target_edge_length > 0))
    fail("target_edge_length", "positive", *o.target_edge_length);
  if (!(std::isfinite(o.edge_length_rel_median) && o.edge_length_rel_median > 0))
    fail("edge_length_rel_median", "positive", o.edge_length_rel_median);
  if (o.iterations < 1 || o.iterations > 100) fail("iterations", "in 1..100", o.iterations);
  if (!(std::isfinite(o.max_face_growth) && o.max_face_growth >= 1)) fail("max_face_growth", ">= 1", o.max_face_growth);
}

}  // namespace

RemeshResult remesh(const TriangleMesh& mesh, const RemeshOptions& options) {
  validate(options);
  const auto t0 = std::chrono::steady_clock::now();
  RemeshResult out;
  out.mesh = mesh;
  out.stats.faces_before = out.stats.faces_after = mesh.triangles.size();
  out.stats.min_angle_deg_before = out.stats.min_angle_deg_after = min_angle_deg(mesh);
  auto finish = [&](std::string warning) {
    if (!warning.empty()) out.warnings.push_back(std::move(warning));
    out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };

  const auto before = topology::analyze_topology(mesh);
  if (const std::string why = unfit_reason(before); !why.empty()) return finish("remeshing skipped: " + why);

  const double target = options.target_edge_length.value_or(options.edge_length_rel_median * median_edge_length(mesh));
  out.stats.target_edge_length = target;
  if (!(target > 0)) return finish("remeshing skipped: the mesh has no edge of positive length");
  // An equilateral triangle of edge `target` covers sqrt(3)/4 target^2.
  const double expected_faces = mesh::total_area(mesh) / (std::sqrt(3.0) / 4.0 * target * target);
  const double max_faces = std::max(1e6, options.max_face_growth * static_cast<double>(before.faces));
  if (expected_faces > max_faces) {
    std::ostringstream s;
    s << "remeshing skipped: a target edge of " << target << " would make about " << std::setprecision(2)
      << expected_faces << " faces, more than " << max_faces << " (" << options.max_face_growth
      << " times the mesh's " << before.faces << ", at least 1M)";
    return finish(s.str());
  }

  TriangleMesh remeshed;
  try {
    remeshed = isotropic_remesh(mesh, target, options.iterations, options.boundary);
  } catch (const NumericalFailure& e) {
    return finish(std::string("remeshing skipped: ") + e.what());
  } catch (const CGAL::Failure_exception& e) {
    return finish("remeshing skipped: CGAL failed (" + e.message() + ")");
  }
  if (const std::string change = topology_change(before, topology::analyze_topology(remeshed)); !change.empty())
    return finish("remeshing undone: " + change);
  out.mesh = std::move(remeshed);
  out.stats.is_remeshed = true;
  out.stats.faces_after = out.mesh.triangles.size();
  out.stats.min_angle_deg_after = min_angle_deg(out.mesh);
  return finish("");
}

}  // namespace envcrust::remesh
