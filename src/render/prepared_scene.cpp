// Validation of a Scene and its move into the unit frame the tracer works in.
#include "prepared_scene.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace envcrust::render::detail {
namespace {

// Distinct tube colours that stay apart from the default front (grey-blue) and back (terracotta).
constexpr Color kLoopPalette[] = {{0.10f, 0.60f, 0.20f}, {0.60f, 0.20f, 0.75f},
                                  {0.95f, 0.70f, 0.05f}, {0.10f, 0.55f, 0.80f},
                                  {0.85f, 0.15f, 0.15f}, {0.30f, 0.30f, 0.30f}};
// Auto radii as fractions of the diagonal of the box of all points (RenderOptions docs).
constexpr double kAutoSphereRadius = 0.004;
constexpr double kAutoTubeRadius = 0.006;

std::string number(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

bool is_finite(const Point3& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

class Box {
 public:
  void add(const Point3& p, double r = 0) {
    lo_ = {std::min(lo_.x, p.x() - r), std::min(lo_.y, p.y() - r), std::min(lo_.z, p.z() - r)};
    hi_ = {std::max(hi_.x, p.x() + r), std::max(hi_.y, p.y() + r), std::max(hi_.z, p.z() + r)};
  }
  [[nodiscard]] bool is_empty() const { return lo_.x > hi_.x; }
  [[nodiscard]] double diagonal() const { return is_empty() ? 0.0 : length(hi_ - lo_); }
  [[nodiscard]] Vec3 centre() const { return 0.5 * (lo_ + hi_); }
  [[nodiscard]] Vec3 lo() const { return lo_; }
  [[nodiscard]] Vec3 hi() const { return hi_; }

 private:
  Vec3 lo_{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi_{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
};

void check_points(const std::vector<Point3>& points, const std::string& what,
                  const char* item) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) {
      throw InvalidInput("render: " + what + " " + item + " " + std::to_string(i) +
                         " has a non-finite coordinate");
    }
  }
}

void check_scene(const Scene& scene) {
  std::size_t items = 0;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const auto& mesh = scene.meshes[m].mesh;
    const std::string what = "mesh " + std::to_string(m);
    check_points(mesh.vertices, what, "vertex");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      for (const Index v : mesh.triangles[t]) {
        if (v >= mesh.vertices.size()) {
          throw InvalidInput("render: " + what + " triangle " + std::to_string(t) +
                             " has vertex index " + std::to_string(v) + ", but the mesh has " +
                             std::to_string(mesh.vertices.size()) + " vertices");
        }
      }
    }
    const auto& colors = scene.meshes[m].vertex_colors;
    if (!colors.empty() && colors.size() != mesh.vertices.size())
      throw InvalidInput("render: " + what + " has " + std::to_string(colors.size()) + " vertex colours for " +
                         std::to_string(mesh.vertices.size()) + " vertices");
    items += mesh.triangles.size();
  }
  for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
    const auto& layer = scene.spheres[s];
    const std::string what = "sphere layer " + std::to_string(s);
    check_points(layer.centres, what, "centre");
    if (!layer.radii.empty() && layer.radii.size() != 1 && layer.radii.size() != layer.centres.size()) {
      throw InvalidInput("render: " + what + " has " + std::to_string(layer.radii.size()) +
                         " radii for " + std::to_string(layer.centres.size()) +
                         " centres (expected 0, 1 or one per centre)");
    }
    for (std::size_t i = 0; i < layer.radii.size(); ++i) {
      if (!(std::isfinite(layer.radii[i]) && layer.radii[i] > 0)) {
        throw InvalidInput("render: " + what + " radius " + std::to_string(i) +
                           " must be finite and > 0 (got " + number(layer.radii[i]) + ")");
      }
    }
    if (!(layer.opacity > 0.0f && layer.opacity <= 1.0f)) {
      throw InvalidInput("render: " + what + " opacity must be in (0, 1] (got " +
                         number(layer.opacity) + ")");
    }
    items += layer.centres.size();
  }
  for (std::size_t c = 0; c < scene.curves.size(); ++c) {
    const auto& layer = scene.curves[c];
    const std::string what = "curve layer " + std::to_string(c);
    if (!(std::isfinite(layer.radius) && layer.radius >= 0)) {
      throw InvalidInput("render: " + what + " radius must be finite and >= 0 (got " +
                         number(layer.radius) + ")");
    }
    for (std::size_t l = 0; l < layer.loops.size(); ++l) {
      const std::string loop = what + " loop " + std::to_string(l);
      if (layer.loops[l].size() < 2) {
        throw InvalidInput("render: " + loop + " needs at least 2 points (got " +
                           std::to_string(layer.loops[l].size()) + ")");
      }
      check_points(layer.loops[l], loop, "point");
    }
    items += layer.loops.size();
  }
  if (items == 0) {
    throw InvalidInput("render: the scene is empty (no triangle, sphere or loop): nothing to draw");
  }
}

Vec3 to_unit(const Point3& p, Vec3 centre, double scale) {
  return (1.0 / scale) * (Vec3{p.x(), p.y(), p.z()} - centre);
}

std::vector<Vec3> signed_vertex_normals(const PreparedMesh& mesh) {
  std::vector<Vec3> normals(mesh.vertices.size());
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]];
    const Vec3 n = cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a);
    for (const Index v : t) {
      normals[v] = dot(normals[v], n) < 0 ? normals[v] - n : normals[v] + n;
    }
  }
  for (auto& n : normals) n = normalized(n);
  return normals;
}

}  // namespace

PreparedScene prepare_scene(const Scene& scene) {
  check_scene(scene);
  Box points;
  for (const auto& layer : scene.meshes)
    for (const auto& t : layer.mesh.triangles)
      for (const Index v : t) points.add(layer.mesh.vertices[v]);
  for (const auto& layer : scene.spheres)
    for (const auto& c : layer.centres) points.add(c);
  for (const auto& layer : scene.curves)
    for (const auto& loop : layer.loops)
      for (const auto& p : loop) points.add(p);
  const double diagonal = points.diagonal();

  // Resolve radii, then let them widen the box the camera is fitted to.
  std::vector<std::vector<double>> sphere_radii;
  Box all = points;
  for (const auto& layer : scene.spheres) {
    std::vector<double> radii(layer.centres.size(), kAutoSphereRadius * diagonal);
    if (layer.radii.size() == 1) std::fill(radii.begin(), radii.end(), layer.radii[0]);
    if (layer.radii.size() > 1) radii = layer.radii;
    for (std::size_t i = 0; i < radii.size(); ++i) all.add(layer.centres[i], radii[i]);
    sphere_radii.push_back(std::move(radii));
  }
  std::vector<double> tube_radii;
  for (const auto& layer : scene.curves) {
    tube_radii.push_back(layer.radius > 0 ? layer.radius : kAutoTubeRadius * diagonal);
    for (const auto& loop : layer.loops)
      for (const auto& p : loop) all.add(p, tube_radii.back());
  }
  if (!(all.diagonal() > 0)) {
    throw DegenerateInput("render: the scene has zero extent (all points coincide and no radius)");
  }

  PreparedScene out;
  const Vec3 centre = all.centre();
  out.scale = 0.5 * all.diagonal();
  out.box_min = to_unit({all.lo().x, all.lo().y, all.lo().z}, centre, out.scale);
  out.box_max = to_unit({all.hi().x, all.hi().y, all.hi().z}, centre, out.scale);
  for (const auto& layer : scene.meshes) {
    PreparedMesh mesh;
    for (const auto& p : layer.mesh.vertices) mesh.vertices.push_back(to_unit(p, centre, out.scale));
    mesh.triangles = layer.mesh.triangles;
    mesh.front = layer.front;
    mesh.back = layer.back;
    mesh.shading = layer.shading;
    mesh.use_wireframe = layer.use_wireframe;
    mesh.vertex_colors = layer.vertex_colors;
    if (mesh.shading == Shading::Smooth) mesh.vertex_normals = signed_vertex_normals(mesh);
    out.meshes.push_back(std::move(mesh));
  }
  for (std::size_t s = 0; s < scene.spheres.size(); ++s) {
    PreparedSpheres spheres;
    for (const auto& c : scene.spheres[s].centres) spheres.centres.push_back(to_unit(c, centre, out.scale));
    for (const double r : sphere_radii[s]) spheres.radii.push_back(r / out.scale);
    spheres.color = scene.spheres[s].color;
    spheres.opacity = scene.spheres[s].opacity;
    out.spheres.push_back(std::move(spheres));
  }
  for (std::size_t c = 0; c < scene.curves.size(); ++c) {
    PreparedCurves curves;
    for (const auto& loop : scene.curves[c].loops) {
      std::vector<Vec3> unit;
      for (const auto& p : loop) unit.push_back(to_unit(p, centre, out.scale));
      curves.loops.push_back(std::move(unit));
    }
    curves.radius = tube_radii[c] / out.scale;
    const auto& colors = scene.curves[c].colors;
    for (std::size_t l = 0; l < curves.loops.size(); ++l) {
      curves.colors.push_back(colors.empty() ? kLoopPalette[l % std::size(kLoopPalette)]
                                             : colors[l % colors.size()]);
    }
    out.curves.push_back(std::move(curves));
  }
  return out;
}

}  // namespace envcrust::render::detail
