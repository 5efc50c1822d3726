// The stages of power_crust and the intermediate results they pass on (docs/method.md §7).
#pragma once

#include "delaunay.h"
#include "power_diagram.h"

#include "envcrust/power_crust.h"

#include <CGAL/Bbox_3.h>

#include <memory>
#include <string>
#include <vector>

namespace envcrust::powercrust {

/// The two labeling thresholds after applying the preset.
struct Thresholds {
  double neighbor = 0.0;     ///< theta (-t)
  double second_pass = 0.0;  ///< theta2 (-w)
  double sampling_estimate = 1.0;  ///< r (-R); 1: off
};

/// Validate the options and resolve the preset.
/// @throws InvalidOptions naming the field and value.
Thresholds check_options(const PowerCrustOptions& options);

/// Refuse fewer than 5 distinct points and collinear or coplanar sets.
/// @throws DegenerateInput.
void check_dimension(const std::vector<Point3>& samples);

/// Poles of the samples, read from the Delaunay triangulation (docs/method.md §7.4).
struct PoleStage {
  std::vector<Pole> poles;
  std::vector<SamplePoles> sample_poles;
  std::vector<DelaunayCell> cells;  ///< only when asked for
  /// Per sample, when asked for: the median nearest-neighbour distance of the sample and its
  /// Delaunay neighbours.
  std::vector<double> local_spacing;
  std::size_t finite_cells = 0;
  std::size_t welded_poles = 0;
};

/// Compute Voronoi vertices, poles (welded where balls agree to ~1e-11 diag, ids in the
/// samples' spatial order) and the opposite-pole weights. Frees the triangulation as soon as
/// the poles are chosen. With `local_spacing`, also each sample's local spacing (the median
/// nearest-neighbour distance over it and its Delaunay neighbours). With sampling_estimate < 1,
/// a sample whose second pole is nearer than the lfs bound is left unpaired
/// (SamplePoles::is_paired false).
PoleStage compute_poles(std::unique_ptr<Delaunay> dt, const std::vector<Point3>& samples, bool keep_cells,
                        bool local_spacing, double sampling_estimate = 1.0);

/// What labeling did beyond setting Pole::label.
struct LabelingReport {
  std::size_t unknown_after_second_pass = 0;
  std::size_t resolved = 0;
};

/// The priority-queue labeling of the original program, with its second pass (docs/method.md §7.6).
/// Poles flagged in `deferred` (empty: none) are not labeled by the priority queue, only by
/// the second pass and the fallback.
LabelingReport label_poles(std::vector<Pole>& poles, const std::vector<SamplePoles>& sample_poles,
                           const PoleGraph& graph, const Thresholds& thresholds,
                           const CGAL::Bbox_3& sample_bbox, bool resolve_unknown,
                           const std::vector<bool>& deferred = {});

/// The crust and where each triangle came from (docs/method.md §7.7).
struct CrustStage {
  TriangleMesh mesh;
  std::vector<std::array<Index, 2>> face_poles;
  std::size_t polygons = 0;
  std::size_t unbounded_faces = 0;
  std::vector<std::string> warnings;
};

/// Power faces between In and Out cells, welded, oriented In -> Out, fan-triangulated.
CrustStage extract_crust(const PowerDiagram& diagram, const std::vector<Pole>& poles);

/// Regular-triangulation simplices among In poles, deduplicated and sorted (docs/method.md §7.8).
PowerShape extract_power_shape(const PowerDiagram& diagram, const std::vector<Pole>& poles);

}  // namespace envcrust::powercrust
