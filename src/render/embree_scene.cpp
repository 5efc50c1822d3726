// Building the Embree scene. Embree works in single precision, which is why the prepared
// scene lives in a unit frame.
#include "embree_scene.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <limits>
#include <string>

namespace envcrust::render::detail {
namespace {

void throw_on_error(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw NumericalFailure(std::string("render: Embree failed to ") + what + " (error code " +
                           std::to_string(static_cast<int>(error)) + ")");
  }
}

// A buffer of `count` items of `per_item` T each (stride per_item * sizeof(T)).
template <class T>
T* new_buffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, std::size_t count,
              std::size_t per_item = 1) {
  return static_cast<T*>(
      rtcSetNewGeometryBuffer(geometry, type, 0, format, per_item * sizeof(T), count));
}

struct Float4 {
  float x, y, z, r;
};

Float4 float4(Vec3 p, double r) {
  return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z),
          static_cast<float>(r)};
}

}  // namespace

EmbreeScene::EmbreeScene(const PreparedScene& scene) {
  // One build thread: the BVH, hence the choice between exactly tied hits, is reproducible.
  device_ = rtcNewDevice("threads=1");
  if (device_ == nullptr) {
    throw NumericalFailure("render: cannot create an Embree device (error code " +
                           std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  }
  try {
    scene_ = rtcNewScene(device_);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) add_mesh(scene.meshes[i], i);
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) add_spheres(scene.spheres[i], i);
    segment_loops_.resize(scene.curves.size());
    for (std::size_t i = 0; i < scene.curves.size(); ++i) add_curves(scene.curves[i], i);
    rtcCommitScene(scene_);
    throw_on_error(device_, "build the scene");
  } catch (...) {
    if (scene_ != nullptr) rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw;
  }
}

EmbreeScene::~EmbreeScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void EmbreeScene::attach(RTCGeometry geometry, LayerKind kind, std::size_t layer) {
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  throw_on_error(device_, "add a geometry");
  if (owners_.size() <= id) owners_.resize(id + 1);
  owners_[id] = {kind, layer};
}

void EmbreeScene::add_mesh(const PreparedMesh& mesh, std::size_t layer) {
  if (mesh.triangles.empty()) return;
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = new_buffer<float>(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3,
                                     mesh.vertices.size(), 3);
  auto* indices = new_buffer<unsigned>(geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT3,
                                       mesh.triangles.size(), 3);
  throw_on_error(device_, "allocate triangle buffers");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    vertices[3 * i] = static_cast<float>(mesh.vertices[i].x);
    vertices[3 * i + 1] = static_cast<float>(mesh.vertices[i].y);
    vertices[3 * i + 2] = static_cast<float>(mesh.vertices[i].z);
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.triangles[t][k];
  attach(geometry, LayerKind::Mesh, layer);
}

void EmbreeScene::add_spheres(const PreparedSpheres& spheres, std::size_t layer) {
  if (spheres.centres.empty()) return;
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* points = new_buffer<Float4>(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT4,
                                    spheres.centres.size());
  throw_on_error(device_, "allocate sphere buffers");
  for (std::size_t i = 0; i < spheres.centres.size(); ++i)
    points[i] = float4(spheres.centres[i], spheres.radii[i]);
  attach(geometry, LayerKind::Spheres, layer);
}

void EmbreeScene::add_curves(const PreparedCurves& curves, std::size_t layer) {
  if (curves.loops.empty()) return;
  // Each closed loop p0..p(n-1) is stored as p(n-1), p0, ..., p(n-1), p0, p1 so that every
  // segment has its neighbours in memory and can be flagged as joined on both sides (no
  // inner caps poking out of the tube).
  std::vector<Float4> vertices;
  std::vector<unsigned> starts;
  for (std::size_t l = 0; l < curves.loops.size(); ++l) {
    const auto& loop = curves.loops[l];
    const std::size_t n = loop.size();
    const auto base = static_cast<unsigned>(vertices.size());
    vertices.push_back(float4(loop[n - 1], curves.radius));
    for (std::size_t i = 0; i <= n; ++i) vertices.push_back(float4(loop[i % n], curves.radius));
    vertices.push_back(float4(loop[1 % n], curves.radius));
    for (std::size_t i = 0; i < n; ++i) {
      starts.push_back(base + 1 + static_cast<unsigned>(i));
      segment_loops_[layer].push_back(static_cast<std::uint32_t>(l));
    }
  }
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  auto* vertex_buffer = new_buffer<Float4>(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT4,
                                           vertices.size());
  auto* index_buffer = new_buffer<unsigned>(geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT,
                                            starts.size());
  auto* flags = new_buffer<unsigned char>(geometry, RTC_BUFFER_TYPE_FLAGS, RTC_FORMAT_UCHAR,
                                          starts.size());
  throw_on_error(device_, "allocate curve buffers");
  std::copy(vertices.begin(), vertices.end(), vertex_buffer);
  std::copy(starts.begin(), starts.end(), index_buffer);
  for (std::size_t i = 0; i < starts.size(); ++i)
    flags[i] = RTC_CURVE_FLAG_NEIGHBOR_LEFT | RTC_CURVE_FLAG_NEIGHBOR_RIGHT;
  attach(geometry, LayerKind::Curves, layer);
}

Hit EmbreeScene::intersect(Vec3 origin, Vec3 direction, double t_near) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit{};
  rayhit.ray.org_x = static_cast<float>(origin.x);
  rayhit.ray.org_y = static_cast<float>(origin.y);
  rayhit.ray.org_z = static_cast<float>(origin.z);
  rayhit.ray.dir_x = static_cast<float>(direction.x);
  rayhit.ray.dir_y = static_cast<float>(direction.y);
  rayhit.ray.dir_z = static_cast<float>(direction.z);
  rayhit.ray.tnear = static_cast<float>(t_near);
  rayhit.ray.tfar = std::numeric_limits<float>::infinity();
  rayhit.ray.mask = 0xFFFFFFFFu;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayhit);
  Hit hit;
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.is_hit = true;
  hit.kind = owners_[rayhit.hit.geomID].kind;
  hit.layer = owners_[rayhit.hit.geomID].layer;
  hit.primitive = rayhit.hit.primID;
  hit.u = rayhit.hit.u;
  hit.v = rayhit.hit.v;
  hit.t = rayhit.ray.tfar;
  hit.geometric_normal = {rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z};
  return hit;
}

}  // namespace envcrust::render::detail
