// The scene after validation: coordinates moved to a unit frame (centre at the origin, half
// diagonal 1) for Embree's single precision, radii and colours resolved, vertex normals.
#pragma once

#include "envcrust/render.h"
#include "vec3.h"

#include <array>
#include <vector>

namespace envcrust::render::detail {

struct PreparedMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<Index, 3>> triangles;
  /// Smooth shading: per vertex, the area-weighted face normals summed with their signs
  /// aligned (so inconsistently oriented and non-orientable meshes still get usable lines).
  std::vector<Vec3> vertex_normals;
  Color front, back;
  Shading shading = Shading::Smooth;
  bool use_wireframe = false;
  std::vector<Color> vertex_colors;  ///< one per vertex, or empty
};

struct PreparedSpheres {
  std::vector<Vec3> centres;
  std::vector<double> radii;  ///< one per centre
  Color color;
  float opacity = 1.0f;
};

struct PreparedCurves {
  std::vector<std::vector<Vec3>> loops;
  double radius = 0;
  std::vector<Color> colors;  ///< one per loop
};

struct PreparedScene {
  std::vector<PreparedMesh> meshes;
  std::vector<PreparedSpheres> spheres;
  std::vector<PreparedCurves> curves;
  Vec3 box_min, box_max;  ///< bounding box in the unit frame, radii included
  double scale = 1;       ///< model units per unit-frame unit
};

/// Validate `scene` and move it into the unit frame.
/// @throws InvalidInput (empty scene, non-finite coordinate, index out of range, bad radius,
///         short loop); DegenerateInput when everything sits at one point with no radius.
PreparedScene prepare_scene(const Scene& scene);

}  // namespace envcrust::render::detail
