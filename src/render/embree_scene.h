// The prepared scene as an Embree scene: triangles, sphere points and round linear curves,
// with the map from Embree's geometry ids back to our layers.
#pragma once

#include "prepared_scene.h"

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

namespace envcrust::render::detail {

enum class LayerKind { Mesh, Spheres, Curves };

/// A ray hit: which layer and primitive, where, and Embree's geometric normal (unnormalised).
struct Hit {
  bool is_hit = false;
  LayerKind kind = LayerKind::Mesh;
  std::size_t layer = 0;
  unsigned primitive = 0;  ///< triangle, sphere, or curve segment index
  float u = 0, v = 0;      ///< barycentrics of the hit in a triangle
  double t = 0;            ///< distance along the ray
  Vec3 geometric_normal;
};

/// Owns an Embree device and a committed scene. Intersection is thread-safe.
class EmbreeScene {
 public:
  /// @throws NumericalFailure when Embree fails (its message included).
  explicit EmbreeScene(const PreparedScene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Closest hit of the ray origin + t * direction, t in (t_near, inf).
  [[nodiscard]] Hit intersect(Vec3 origin, Vec3 direction, double t_near) const;
  /// The loop a curve segment belongs to.
  [[nodiscard]] std::size_t loop_of_segment(std::size_t layer, unsigned segment) const {
    return segment_loops_[layer][segment];
  }

 private:
  void add_mesh(const PreparedMesh& mesh, std::size_t layer);
  void add_spheres(const PreparedSpheres& spheres, std::size_t layer);
  void add_curves(const PreparedCurves& curves, std::size_t layer);
  void attach(RTCGeometry geometry, LayerKind kind, std::size_t layer);

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  struct Owner {
    LayerKind kind;
    std::size_t layer;
  };
  std::vector<Owner> owners_;  ///< by Embree geometry id
  std::vector<std::vector<std::uint32_t>> segment_loops_;  ///< per curve layer, per segment
};

}  // namespace envcrust::render::detail
