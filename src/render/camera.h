// The orthographic camera: its frame from a View and its fit to the scene's bounding box.
#pragma once

#include "envcrust/render.h"
#include "vec3.h"

namespace envcrust::render::detail {

struct Camera {
  Vec3 right, up, forward;  ///< orthonormal; forward points from the camera into the scene
  Vec3 target;              ///< the point seen at the image centre
  double pixel_size = 1;    ///< scene units per pixel
  int width = 0, height = 0;
  double ray_start = 0;     ///< distance behind the target where rays start (outside the box)
};

/// Fit the camera so that the box's 8 projected corners span (1 - 2 margin) of the image in
/// its tighter dimension, centred (RenderOptions::margin).
Camera fit_camera(Vec3 box_min, Vec3 box_max, const View& view, int width, int height,
                  double margin);

/// Origin of the ray through the continuous pixel position (x right, y down, (0, 0) is the
/// top-left corner of the image); its direction is camera.forward.
Vec3 ray_origin(const Camera& camera, double x, double y);

}  // namespace envcrust::render::detail
