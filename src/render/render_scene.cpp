// render_scene: validation, the Embree scene, and the per-pixel tracing loop (supersampled,
// translucent spheres by continuing the ray, rows in parallel).
#include "camera.h"
#include "embree_scene.h"
#include "prepared_scene.h"
#include "shading.h"

#include "envcrust/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace envcrust::render {
namespace {

using detail::Hit;
using detail::LayerKind;
using detail::Rgb;
using detail::Vec3;

// Translucent layers a ray passes through before it stops (beyond them the rest is dimmed
// below visibility anyway at the usual ball opacity 0.3).
constexpr int kMaxLayers = 16;
// Remaining transmission below which a ray stops: under half an 8-bit step.
constexpr double kMinTransmission = 1.0 / 512.0;
// Pixels closer than this many pixel widths to a triangle edge are darkened (wireframe).
constexpr double kWireHalfWidthPx = 0.6;
// Back faces of a mesh drawn with vertex colours: the value colour at this brightness.
constexpr double kBackFaceValueShade = 0.7;

void check_options(const RenderOptions& o) {
  auto fail = [](const std::string& field, const std::string& range, double value) {
    std::ostringstream s;
    s << "RenderOptions." << field << " must be in " << range << " (got " << value << ")";
    throw InvalidOptions(s.str());
  };
  if (o.width < 16 || o.width > 8192) fail("width", "[16, 8192]", o.width);
  if (o.height < 16 || o.height > 8192) fail("height", "[16, 8192]", o.height);
  if (o.supersampling < 1 || o.supersampling > 4) fail("supersampling", "[1, 4]", o.supersampling);
  if (!(o.margin >= 0 && o.margin <= 0.45)) fail("margin", "[0, 0.45]", o.margin);
  if (!std::isfinite(o.view.azimuth_deg)) fail("view.azimuth_deg", "finite values", o.view.azimuth_deg);
  if (!std::isfinite(o.view.elevation_deg) || std::abs(o.view.elevation_deg) > 90)
    fail("view.elevation_deg", "[-90, 90]", o.view.elevation_deg);
}

/// A surface point ready for shading: base colour, unit normal facing the viewer, opacity.
struct Surface {
  Rgb base;
  Vec3 normal;
  double opacity = 1;
  bool is_skipped = false;  ///< back side of a translucent sphere: pass through unlit
};

class Tracer {
 public:
  Tracer(const detail::PreparedScene& scene, const detail::EmbreeScene& embree,
         const detail::Camera& camera, const RenderOptions& options)
      : scene_(scene), embree_(embree), camera_(camera),
        lights_(detail::make_lights(camera.right, camera.up, camera.forward)),
        background_(detail::to_linear(options.background)) {
    for (const auto& m : scene.meshes) {
      mesh_colors_.push_back({detail::to_linear(m.front), detail::to_linear(m.back), {}});
      for (const auto& c : m.vertex_colors) mesh_colors_.back().per_vertex.push_back(detail::to_linear(c));
    }
    for (const auto& s : scene.spheres) sphere_colors_.push_back(detail::to_linear(s.color));
    for (const auto& c : scene.curves) {
      curve_colors_.emplace_back();
      for (const auto& color : c.colors) curve_colors_.back().push_back(detail::to_linear(color));
    }
  }

  /// Colour (linear) seen through the continuous pixel position (x, y).
  [[nodiscard]] Rgb trace(double x, double y) const {
    const Vec3 origin = detail::ray_origin(camera_, x, y);
    const Vec3 direction = camera_.forward;
    Rgb colour;
    double transmission = 1;
    double t_near = 0;
    for (int layer = 0; layer < kMaxLayers; ++layer) {
      const Hit hit = embree_.intersect(origin, direction, t_near);
      if (!hit.is_hit) break;
      // Continue just past the hit; Embree's float t has ~1e-7 relative precision.
      t_near = hit.t * (1 + 1e-5) + 1e-6;
      const Surface s = surface(hit, origin + hit.t * direction);
      if (s.is_skipped) continue;
      colour = colour + (transmission * s.opacity) * detail::shade(s.base, s.normal, lights_);
      transmission *= 1 - s.opacity;
      if (transmission < kMinTransmission) return colour;
    }
    return colour + transmission * background_;
  }

 private:
  [[nodiscard]] Vec3 facing_viewer(Vec3 n) const {
    n = detail::normalized(n);
    return dot(n, camera_.forward) > 0 ? -n : n;
  }

  [[nodiscard]] Surface surface(const Hit& hit, Vec3 point) const {
    switch (hit.kind) {
      case LayerKind::Mesh: return mesh_surface(hit);
      case LayerKind::Spheres: {
        const auto& layer = scene_.spheres[hit.layer];
        const Vec3 outward = detail::normalized(point - layer.centres[hit.primitive]);
        Surface s{sphere_colors_[hit.layer], facing_viewer(outward), layer.opacity};
        s.is_skipped = layer.opacity < 1 && dot(outward, camera_.forward) > 0;
        return s;
      }
      case LayerKind::Curves: {
        const std::size_t loop = embree_.loop_of_segment(hit.layer, hit.primitive);
        return {curve_colors_[hit.layer][loop], facing_viewer(hit.geometric_normal), 1.0};
      }
    }
    return {};
  }

  [[nodiscard]] Surface mesh_surface(const Hit& hit) const {
    const auto& mesh = scene_.meshes[hit.layer];
    const auto& tri = mesh.triangles[hit.primitive];
    const Vec3 a = mesh.vertices[tri[0]], b = mesh.vertices[tri[1]], c = mesh.vertices[tri[2]];
    // The winding normal decides front versus back (Embree's own Ng convention aside).
    const Vec3 winding = cross(b - a, c - a);
    const bool is_front = dot(winding, camera_.forward) < 0;
    const double weights[3] = {1.0 - hit.u - hit.v, hit.u, hit.v};
    Vec3 normal = winding;
    if (mesh.shading == Shading::Smooth) {
      Vec3 sum;
      for (int k = 0; k < 3; ++k) {
        const Vec3 n = mesh.vertex_normals[tri[k]];
        sum = sum + (dot(n, winding) < 0 ? -weights[k] : weights[k]) * n;
      }
      if (length(sum) > 1e-12) normal = sum;
    }
    const MeshColors& colors = mesh_colors_[hit.layer];
    Rgb base = is_front ? colors.front : colors.back;
    if (!colors.per_vertex.empty()) {
      base = {};
      for (int k = 0; k < 3; ++k) base = base + weights[k] * colors.per_vertex[tri[k]];
      if (!is_front) base = kBackFaceValueShade * base;
    }
    if (mesh.use_wireframe && near_edge(a, b, c, winding, weights)) base = 0.3 * base;
    return {base, facing_viewer(normal), 1.0};
  }

  [[nodiscard]] bool near_edge(Vec3 a, Vec3 b, Vec3 c, Vec3 winding, const double* weights) const {
    // Distance to the edge opposite corner k is weight_k times the height over that edge.
    const double twice_area = length(winding);
    const double opposite[3] = {length(c - b), length(a - c), length(b - a)};
    for (int k = 0; k < 3; ++k) {
      if (opposite[k] > 0 && weights[k] * twice_area / opposite[k] < kWireHalfWidthPx * camera_.pixel_size)
        return true;
    }
    return false;
  }

  struct MeshColors {
    Rgb front, back;
    std::vector<Rgb> per_vertex;  ///< linear light; empty: front and back
  };
  const detail::PreparedScene& scene_;
  const detail::EmbreeScene& embree_;
  const detail::Camera& camera_;
  detail::Lights lights_;
  Rgb background_;
  std::vector<MeshColors> mesh_colors_;
  std::vector<Rgb> sphere_colors_;
  std::vector<std::vector<Rgb>> curve_colors_;
};

}  // namespace

Image render_scene(const Scene& scene, const RenderOptions& options) {
  check_options(options);
  const detail::PreparedScene prepared = detail::prepare_scene(scene);
  const detail::EmbreeScene embree(prepared);
  const detail::Camera camera = detail::fit_camera(prepared.box_min, prepared.box_max, options.view,
                                                   options.width, options.height, options.margin);
  const Tracer tracer(prepared, embree, camera, options);

  Image image;
  image.width = options.width;
  image.height = options.height;
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  const int n = options.supersampling;
  const double weight = 1.0 / (n * n);
  // Each row writes only its own pixels, so the image does not depend on the thread count.
  tbb::parallel_for(tbb::blocked_range<int>(0, image.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < image.width; ++x) {
        Rgb sum;
        for (int sy = 0; sy < n; ++sy)
          for (int sx = 0; sx < n; ++sx)
            sum = sum + tracer.trace(x + (sx + 0.5) / n, y + (sy + 0.5) / n);
        sum = weight * sum;
        std::uint8_t* pixel = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
        pixel[0] = detail::to_srgb_byte(sum.r);
        pixel[1] = detail::to_srgb_byte(sum.g);
        pixel[2] = detail::to_srgb_byte(sum.b);
      }
    }
  });
  return image;
}

}  // namespace envcrust::render
