// Input preparation: a point set, a triangle mesh or a patch model as read, turned into the
// samples of M that pipeline::reconstruct takes (stray samples removed, normal lines, sharp
// creases, boundary curves, the points' attributes), as `envcrust reconstruct FILE` does.
//
// The stage reads no file and prints nothing: the caller reads (io::read_attributed_points,
// io::read_triangle_mesh) and decides what to show of the result's notes.
#pragma once

#include "envcrust/attributes.h"
#include "envcrust/boundary.h"
#include "envcrust/envelope.h"
#include "envcrust/errors.h"
#include "envcrust/models.h"
#include "envcrust/pipeline.h"
#include "envcrust/progress.h"
#include "envcrust/surfaces.h"
#include "envcrust/types.h"

#include <optional>
#include <string>
#include <vector>

namespace envcrust::input {

/// What is done where the surface bends by more than 80 degrees along creases longer in all
/// than a tenth of the bounding-box diagonal (a mesh's sharp edges, a point set's normals that
/// jump). The sheet pairs samples whose offset directions make at least 100 degrees, so such
/// a crease would tear it apart (measured: a square sheet folded by 90 degrees came out in two
/// pieces; docs/reconstruct.md, sharp creases).
enum class CreaseMode {
  /// Fitted normal lines replace the given normals: the creases are rounded off, and the
  /// result lies closer to the creased surface (open box, 10,000 points: 1.14% / 2.40% of
  /// the diagonal against 2.25% / 2.46% joined).
  Round,
  /// The normals are kept and the creases handed to the envelope and the sheet
  /// (envelope::SurfaceSamples::creases), which join across them.
  Join,
};

/// Options of the input stage (`envcrust reconstruct` binds its flags to these fields).
struct InputOptions {
  /// Names the input at the head of the stage's messages ("scan.xyz: need at least 5 distinct
  /// points, got 3"), as io names a file; empty: messages name nothing.
  std::string name;
  /// Points: remove the stray samples outliers::find_outliers flags before anything else
  /// (`--keep-outliers` turns it off). On: a scan's stray points become spikes in the result.
  bool use_outlier_removal = true;
  /// Points without given boundary points: detect boundary curves (boundary::detect_boundary);
  /// false reads the points as samples of a closed surface (`--no-boundary`).
  bool use_boundary_detection = true;
  /// Points: options of the boundary detector, or of boundary::boundary_from_points when
  /// boundary points are given.
  boundary::BoundaryOptions boundary;
  /// Meshes, patch models and points with normals: what is done with sharp creases.
  CreaseMode creases = CreaseMode::Round;
  /// Points: keep only those whose "classification" attribute is one of these (a LAS file's
  /// classes: 2 ground, 6 building, ...), before anything else; empty: every point.
  std::vector<int> classes;
  /// Points and meshes lying farther from (0, 0, 0) than 100 times their diagonal (a scan in
  /// UTM metres, ~500,000 / 5,000,000): work relative to a local origin near them
  /// (PreparedInput::origin), as the stages' squared distances would spend the digits of the
  /// shape on the position. false: the coordinates as given.
  bool use_local_origin = true;
};

/// Boundary points given for a point set instead of detected (`--boundary FILE`): each marks
/// its nearest sample (boundary::boundary_from_points).
struct GivenBoundary {
  PointSet points;   ///< in any order, several loops; normals (outward conormals) optional
  std::string name;  ///< names them at the head of messages about them (their files); may be empty
};

/// A point set to prepare, as read.
struct PointInput {
  /// The points, their normals if any (at any length, or all (0, 0, 0): none given) and the
  /// points' attributes (empty or one value per point).
  AttributedPoints points;
  /// The normals are columns 4-6 of a text file (io::is_text_point_file): when every one is
  /// a whole number in 0..255 and some is above 1 they are colours (x y z r g b, a common
  /// export) and are read so. Normals so read would all point into one octant.
  bool are_normals_text_columns = false;
  /// Boundary points given; nullopt: detected, or none (InputOptions::use_boundary_detection).
  std::optional<GivenBoundary> given_boundary;
};

/// Samples of M and how they were obtained.
struct PreparedInput {
  envelope::SurfaceSamples samples;  ///< unit normal lines; boundary curves; creases (CreaseMode::Join)
  /// The input's coordinates are the samples' plus this (and those of `outliers` and
  /// `attribute_points`): a local origin near an input far from (0, 0, 0) for its size
  /// (InputOptions::use_local_origin), else zero. Add it back to what is written
  /// (restore_origin), and subtract it from a reference given in the input's coordinates.
  Vector3 origin = CGAL::NULL_VECTOR;
  /// What reconstruct's defaults depend on (pipeline::options_for_input): built-in or not,
  /// normals estimated, a mesh's own orientability and genus, boundary detected.
  pipeline::InputKind kind;
  /// Boundary detected: what the detector found besides the curves (moved into
  /// samples.boundary): flagged points, loop widths, dropped loops, its spacing.
  std::optional<boundary::BoundaryDetection> detection;
  /// What was done, one line each, in order: "3 duplicate points merged", "normal lines
  /// estimated by PCA over 24 neighbours", "boundary detected: 1 curves (0 short loops dropped)".
  std::vector<std::string> notes;
  /// What the input makes the reconstruction likely to get wrong (none found by this stage yet).
  std::vector<std::string> warnings;
  std::vector<Point3> outliers;  ///< points: the stray samples removed
  /// Points: the attributes of the samples kept, at `attribute_points` (the kept points), for
  /// the output's vertices (attributes::carry_nearest). Empty when the input has none.
  std::vector<Point3> attribute_points;
  PointAttributes attributes;
};

/// A mesh whose faces form no surface (an edge with 3 faces, a vertex where two fans meet):
/// its vertices can still be prepared as points (prepare_points).
class NotASurface : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// Samples of M from a point set: normals scaled to unit length, repeated points merged (each
/// keeping its first occurrence's normal and attributes), stray samples removed, normal lines
/// fitted by PCA when none are given (or, CreaseMode::Round, when the given ones jump across
/// long creases; then turned to agree with them), and boundary curves given, detected or none.
/// Only the points of InputOptions::classes are kept, first; an input far from the origin
/// is moved to a local one (PreparedInput::origin), the given boundary points with it. One
/// neighbour search serves outliers, normals and detection.
/// @param progress reports "input: neighbours", "input: outliers", "input: creases",
///   "input: normals", "input: boundary".
/// @throws InvalidInput "point 7 has a zero normal"; "no point is of class 7 (the points' classes:
///   1 (120 points), 2 (3000 points))", "the points have no classification to choose classes 2
///   from (...)"; about the given boundary points, named by GivenBoundary::name.
/// @throws DegenerateInput "need at least 5 distinct points, got 2 (48 duplicates merged)",
///   "all 100 points lie on a line (...): no surface to reconstruct". Messages start with
///   InputOptions::name when it is set ("scan.xyz: ...").
PreparedInput prepare_points(PointInput input, const InputOptions& options = {}, const Progress& progress = {});

/// A triangle mesh to prepare, as read.
struct MeshInput {
  TriangleMesh mesh;
  /// Empty, or one value per vertex of `mesh` (a PLY's vertex colours and other vertex
  /// properties, as io::read_attributed_points reads them from the same file).
  PointAttributes vertex_attributes;
};

/// Samples of M from a triangle mesh: vertices at the same coordinates welded, repeated and
/// degenerate faces dropped; the used vertices with area-weighted normal lines and the face
/// centres with face normals; the border loops as boundary curves; the mesh's orientability
/// and genus in `kind`; long sharp creases rounded off or joined (InputOptions::creases); a mesh
/// far from the origin moved to a local one (PreparedInput::origin). The vertex attributes of
/// the vertices faces use go to attribute_points and attributes, in the samples' frame.
/// @throws InvalidInput "the mesh has no faces", "the mesh has no faces but 2 that use a vertex
///   twice", "the mesh has no face of positive area", a non-finite vertex ("vertex 3 ..."),
///   "the vertex colours number 3 for 4 vertices" (the same for a scalar attribute, by name).
/// @throws NotASurface "edge (0, 1) has 3 faces: the mesh is not a surface".
PreparedInput prepare_mesh(MeshInput input, const InputOptions& options = {});

/// prepare_mesh of a mesh without vertex attributes.
PreparedInput prepare_mesh(TriangleMesh mesh, const InputOptions& options = {});

/// Points of the prepared samples' frame moved back to the input's coordinates: each plus
/// `origin` (PreparedInput::origin); nothing happens when it is zero.
void restore_origin(std::vector<Point3>& points, const Vector3& origin);

/// Samples of M drawn from a patch model (a built-in surface or the patches of a NURBS file):
/// `sampling` points with their exact normals, the model's exact boundary curves, its genus
/// (several patches), and the creases where patches meet at an angle rounded off or joined.
/// `kind.is_builtin` stays true: exact samples get no scan settings. The origin stays zero.
/// @throws InvalidOptions as surfaces::sample_surface does.
PreparedInput prepare_model(const models::PatchModel& model, const surfaces::SampleOptions& sampling,
                            const InputOptions& options = {});

}  // namespace envcrust::input
