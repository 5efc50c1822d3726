// Samples of M drawn from a patch model: exact normals and boundary curves, and the creases
// where its patches meet at an angle.
#include "creases.h"

#include "envcrust/input.h"
#include "envcrust/mesh.h"

#include <utility>

namespace envcrust::input {
namespace {

// Several patches joined: a known genus (the adaptive retry's bound), and creases where the
// patches meet at an angle (a box of flat faces), handled as a point set's jumping normals are.
void add_model_creases(const models::PatchModel& model, CreaseMode mode, PreparedInput& out) {
  out.notes.push_back(model.description());
  out.kind.genus = model.genus();
  auto sharp = mesh::sharp_edges(model.truth(), kTearingBendDeg);
  if (!is_long_crease(sharp, model.truth().vertices)) return;
  out.notes.push_back(crease_note("the patches meet", sharp, "edges", mode));
  if (mode == CreaseMode::Join) {
    out.samples.creases = std::move(sharp.segments);
  } else {
    out.samples.normals = fitted_like(out.samples.points, out.samples.normals);
    out.kind.are_normals_estimated = true;
    out.kind.are_signs_given = true;  // the fitted lines face like the patches' normals
  }
}

}  // namespace

PreparedInput prepare_model(const models::PatchModel& model, const surfaces::SampleOptions& sampling,
                            const InputOptions& options) {
  PreparedInput out;
  surfaces::SampleOptions with_normals = sampling;
  with_normals.with_normals = true;
  PointSet points = model.sample(with_normals);
  out.samples.points = std::move(points.points);
  out.samples.normals = std::move(points.normals);
  out.samples.boundary = model.boundary_curves(0.005 * model.diagonal());
  out.notes.push_back("exact normals and boundary curves of " + model.name());
  if (model.patch_count() > 1) add_model_creases(model, options.creases, out);
  return out;
}

}  // namespace envcrust::input
