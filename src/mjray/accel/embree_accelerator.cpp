#include "mjray/accel/embree_accelerator.h"

#include <embree3/rtcore.h>

#include <cfloat>
#include <string>
#include <vector>

#include "mjray/core/error.h"

namespace mjray {

namespace {

constexpr unsigned kTriangleGeometry = 0;
constexpr unsigned kShapeGeometry = 1;

// Embree includes tnear in its range; the smallest normal float keeps t == 0 hits (origin on
// the surface) out, as mjray's open range (0, t_max) requires.
constexpr float kTNear = FLT_MIN;

bool count_device_bytes(void* counter, ssize_t bytes, bool /*post*/) {
  static_cast<std::atomic<int64_t>*>(counter)->fetch_add(int64_t(bytes), std::memory_order_relaxed);
  return true;
}

std::string error_text(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

// The shapes' user geometry: bounds and hits come from the World itself.
void shape_bounds(const RTCBoundsFunctionArguments* args) {
  const World& world = *static_cast<const World*>(args->geometryUserPtr);
  const Bounds3 b = world.primitive_bounds(uint32_t(world.triangles.size()) + args->primID);
  *args->bounds_o = {b.lo.x, b.lo.y, b.lo.z, 0, b.hi.x, b.hi.y, b.hi.z, 0};
}

Ray ray_of(RTCRayN* ray, unsigned n, unsigned i) {
  return {{RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)},
          {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)}};
}

void shape_intersect(const RTCIntersectFunctionNArguments* args) {
  const World& world = *static_cast<const World*>(args->geometryUserPtr);
  const uint32_t prim = uint32_t(world.triangles.size()) + args->primID;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    const auto hit = world.intersect_primitive(prim, ray_of(rays, args->N, i), RTCRayN_tfar(rays, args->N, i));
    if (!hit) continue;
    RTCRayN_tfar(rays, args->N, i) = hit->t;
    RTCHitN_u(hits, args->N, i) = 0;
    RTCHitN_v(hits, args->N, i) = 0;
    RTCHitN_Ng_x(hits, args->N, i) = 0;  // shading data comes from World::interaction
    RTCHitN_Ng_y(hits, args->N, i) = 0;
    RTCHitN_Ng_z(hits, args->N, i) = 1;
    RTCHitN_primID(hits, args->N, i) = args->primID;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
  }
}

void shape_occluded(const RTCOccludedFunctionNArguments* args) {
  const World& world = *static_cast<const World*>(args->geometryUserPtr);
  const uint32_t prim = uint32_t(world.triangles.size()) + args->primID;
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    if (world.intersect_primitive(prim, ray_of(args->ray, args->N, i), RTCRayN_tfar(args->ray, args->N, i)))
      RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;  // Embree's "occluded" mark
  }
}

RTCRay embree_ray(const Ray& ray, float t_max) {
  RTCRay r{};
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tnear = kTNear;
  r.tfar = t_max;
  r.mask = ~0u;
  r.flags = 0;
  return r;
}

// Embree leaves rays with NaN or infinite components undefined; mjray says "no hit".
bool valid_query(const Ray& ray, float t_max) {
  return t_max > kTNear && is_finite(ray.origin) && is_finite(ray.direction);
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(const World& world, int threads, bool exact_hits)
    : world_(world), bounds_(world.bounds()), exact_hits_(exact_hits) {
  // Create the device, counting every byte it allocates.
  const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw SceneError("embree: cannot create a device (" + error_text(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceMemoryMonitorFunction(device_, count_device_bytes, &device_bytes_);
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  // Robust mode makes Embree's triangle test watertight, as mjray's own (Woop et al.) is.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);

  // Triangles: one geometry with all meshes' world-space vertices, in primitive order.
  if (!world.triangles.empty()) {
    std::vector<uint32_t> first_vertex(world.meshes.size() + 1, 0);
    for (size_t m = 0; m < world.meshes.size(); ++m)
      first_vertex[m + 1] = first_vertex[m] + uint32_t(world.meshes[m].positions.size());
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), first_vertex.back()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), world.triangles.size()));
    if (vertices && indices) {
      for (size_t m = 0; m < world.meshes.size(); ++m)
        for (size_t v = 0; v < world.meshes[m].positions.size(); ++v) {
          const Point3& p = world.meshes[m].positions[v];
          float* out = vertices + 3 * (first_vertex[m] + v);
          out[0] = p.x, out[1] = p.y, out[2] = p.z;
        }
      for (size_t t = 0; t < world.triangles.size(); ++t) {
        const WorldTriangle& tri = world.triangles[t];
        const auto& corners = world.meshes[tri.mesh].triangles[tri.face];
        for (int k = 0; k < 3; ++k) indices[3 * t + k] = first_vertex[tri.mesh] + uint32_t(corners[k].position);
      }
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene_, geometry, kTriangleGeometry);
    rtcReleaseGeometry(geometry);
  }

  // Spheres and cubes: one user geometry that defers to the World.
  if (!world.shapes.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(world.shapes.size()));
    rtcSetGeometryUserData(geometry, const_cast<World*>(&world));
    rtcSetGeometryBoundsFunction(geometry, shape_bounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, shape_intersect);
    rtcSetGeometryOccludedFunction(geometry, shape_occluded);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene_, geometry, kShapeGeometry);
    rtcReleaseGeometry(geometry);
  }

  rtcCommitScene(scene_);
  if (const RTCError error = rtcGetDeviceError(device_); error != RTC_ERROR_NONE) {
    release();
    throw SceneError("embree: cannot build the scene (" + error_text(error) + ")");
  }
}

EmbreeAccelerator::~EmbreeAccelerator() { release(); }

void EmbreeAccelerator::release() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
  scene_ = nullptr;
  device_ = nullptr;
}

size_t EmbreeAccelerator::memory_bytes() const {
  const int64_t bytes = device_bytes_.load(std::memory_order_relaxed);
  return bytes > 0 ? size_t(bytes) : 0;
}

std::optional<Hit> EmbreeAccelerator::intersect(const Ray& ray, float t_max) const {
  if (!valid_query(ray, t_max)) return std::nullopt;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit;
  rayhit.ray = embree_ray(ray, t_max);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  if (rayhit.hit.geomID == kShapeGeometry)
    return Hit{rayhit.ray.tfar, uint32_t(world_.triangles.size()) + rayhit.hit.primID};
  // Recompute the hit with mjray's own watertight test, so that t, u and v (and with them
  // the image) are bit for bit those of every other accelerator. Embree's (u, v) weight
  // vertices 1 and 2 as mjray's (b1, b2) do; they are the fallback should the exact test
  // miss a triangle Embree grazed.
  const uint32_t prim = rayhit.hit.primID;
  if (exact_hits_)
    if (auto exact = world_.intersect_primitive(prim, ray, kInfinity)) return exact;
  return Hit{rayhit.ray.tfar, prim, rayhit.hit.u, rayhit.hit.v};
}

bool EmbreeAccelerator::occluded(const Ray& ray, float t_max) const {
  if (!valid_query(ray, t_max)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = embree_ray(ray, t_max);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0;
}

}  // namespace mjray
