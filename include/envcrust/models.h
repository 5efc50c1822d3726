// Several parametric patches joined into one surface where their edges meet: the faces of a
// CAD model (an IGES file of trimmed NURBS patches), read as one exact input.
#pragma once

#include "envcrust/surfaces.h"
#include "envcrust/types.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::models {

/// Options of PatchModel.
struct JoinOptions {
  /// Border edges of two patches closer than this fraction of the model's bounding-box
  /// diagonal are one edge of the model (CAD faces meet within the modeller's tolerance, not
  /// exactly). Above the tessellations' chord error (1e-4 of each patch's diagonal).
  double tolerance_rel_diag = 5e-4;
};

/// What joining the patches found.
struct JoinStats {
  std::size_t patches = 0;
  /// Edges of the joined tessellation whose two faces come from different patches.
  std::size_t joined_edges = 0;
  /// Border edges of one patch split where another patch's border vertices lie on them.
  std::size_t split_edges = 0;
  /// The largest distance between the patches' borders where they were joined.
  double largest_gap = 0;
  double tolerance = 0;  ///< the tolerance used, in model units
  /// Border vertices left open that lie within 20 tolerances of another patch's border (faces
  /// of a model meant to meet, less closely than the tolerance), and the nearest such gap.
  std::size_t near_misses = 0;
  double nearest_miss = 0;
};

/// Border edges of the patches' tessellations that lie within `tolerance` of another patch's
/// border are joined: each border edge is split where a border vertex of another patch lies on
/// it (its triangle fanned), and border vertices of different patches within `tolerance` are
/// welded. The result's faces keep their windings (they may disagree between patches).
struct JoinedMesh {
  TriangleMesh mesh;
  JoinStats stats;
};
JoinedMesh join_tessellations(const std::vector<TriangleMesh>& patches, double tolerance);

/// One patch, or several joined along the edges they share (JoinOptions::tolerance_rel_diag).
/// Everything a parametric input offers the commands: exact samples with their normals, the
/// model's boundary curves (the patches' border edges shared with no other patch), a ground
/// truth tessellation and the topology a reconstruction must have. A single patch is the
/// surface as it is (its own tessellation, boundary curves and expected topology).
class PatchModel {
 public:
  /// @throws InvalidInput with a one-line reason: no patch; patches whose joined tessellation
  ///   is no surface ("3 patches meet along an edge near (x, y, z)", "patches touch at 2
  ///   points only, near (x, y, z)").
  PatchModel(std::vector<std::unique_ptr<surfaces::Surface>> patches, std::string name,
             const JoinOptions& options = {});
  ~PatchModel();
  PatchModel(PatchModel&&) noexcept;
  PatchModel& operator=(PatchModel&&) noexcept;

  [[nodiscard]] const std::string& name() const { return name_; }
  /// The surface's own description, or "4 patches joined along 96 edges (largest gap 1e-06)".
  [[nodiscard]] std::string description() const;
  [[nodiscard]] std::size_t patch_count() const { return patches_.size(); }
  [[nodiscard]] const surfaces::Surface& patch(std::size_t i) const { return *patches_[i]; }
  /// The ground truth: a fine tessellation with the model's topology (surfaces::tessellate of
  /// each patch, joined).
  [[nodiscard]] const TriangleMesh& truth() const { return truth_; }
  [[nodiscard]] const surfaces::ExpectedTopology& expected_topology() const { return expected_; }
  /// Handles and cross-caps summed over the pieces (topology::total_genus of the ground truth);
  /// unset for a single patch (not computed: the surface gives its topology itself).
  [[nodiscard]] std::optional<long> genus() const { return genus_; }
  [[nodiscard]] const JoinStats& joins() const { return joins_; }
  /// Bounding-box diagonal (a single patch's surfaces::bbox_diagonal; of the ground truth for several).
  [[nodiscard]] double diagonal() const { return diagonal_; }

  /// The boundary loops, consecutive vertices at most `max_spacing` apart, with frames
  /// (several patches: the pieces of the patches' exact curves on the joined border loops).
  [[nodiscard]] std::vector<BoundaryCurve> boundary_curves(double max_spacing) const;

  /// `options.count` points uniformly by area over all patches (each patch's count in
  /// proportion to its tessellation's area, largest remainders first), exact normals when
  /// asked, noise as a fraction of the model's diagonal; deterministic for a seed.
  /// @throws InvalidOptions as surfaces::sample_surface.
  [[nodiscard]] PointSet sample(const surfaces::SampleOptions& options) const;

 private:
  std::vector<std::unique_ptr<surfaces::Surface>> patches_;
  std::string name_;
  TriangleMesh truth_;
  surfaces::ExpectedTopology expected_;
  JoinStats joins_;
  std::vector<double> areas_;
  std::optional<long> genus_;  ///< of each patch's tessellation (several patches only)
  double diagonal_ = 0;
};

}  // namespace envcrust::models
