// Orthographic camera fitted to a bounding box: a scientific view without perspective
// distortion, so silhouettes can be checked against analytic projections.
#include "camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace envcrust::render::detail {

Camera fit_camera(Vec3 box_min, Vec3 box_max, const View& view, int width, int height,
                  double margin) {
  const double az = view.azimuth_deg * std::numbers::pi / 180.0;
  const double el = view.elevation_deg * std::numbers::pi / 180.0;
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.forward = -Vec3{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  // Horizontal right vector from the azimuth alone: well defined at the poles too.
  camera.right = {-std::sin(az), std::cos(az), 0.0};
  camera.up = cross(camera.right, camera.forward);
  camera.target = 0.5 * (box_min + box_max);

  double half_u = 0, half_v = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{corner & 1 ? box_max.x : box_min.x, corner & 2 ? box_max.y : box_min.y,
                 corner & 4 ? box_max.z : box_min.z};
    const Vec3 d = p - camera.target;
    half_u = std::max(half_u, std::abs(dot(d, camera.right)));
    half_v = std::max(half_v, std::abs(dot(d, camera.up)));
  }
  const double fill = 1.0 - 2.0 * margin;
  camera.pixel_size = std::max(2.0 * half_u / (fill * width), 2.0 * half_v / (fill * height));
  if (!(camera.pixel_size > 0)) camera.pixel_size = 1.0 / std::max(width, height);
  camera.ray_start = length(box_max - box_min) + 1.0;
  return camera;
}

Vec3 ray_origin(const Camera& camera, double x, double y) {
  const double u = (x - 0.5 * camera.width) * camera.pixel_size;
  const double v = (0.5 * camera.height - y) * camera.pixel_size;
  return camera.target + u * camera.right + v * camera.up - camera.ray_start * camera.forward;
}

}  // namespace envcrust::render::detail
