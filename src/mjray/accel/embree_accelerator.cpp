#include "mjray/accel/embree_accelerator.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cfloat>
#include <string>
#include <vector>

#include "mjray/core/error.h"
#include "mjray/core/float_steps.h"

namespace mjray {

namespace {

constexpr unsigned kTriangleGeometry = 0;
constexpr unsigned kUserGeometry = 1;

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

using UserPrimitives = EmbreeAccelerator::UserPrimitives;

/// A query's context: Embree's own first, so that callbacks get back to the rest from the
/// pointer Embree passes them.
struct QueryContext {
  RTCIntersectContext embree;
  const PrimitiveSet* prims;
  Interval t_range;             ///< the query's own (the Embree ray's is wider, see embree_ray)
  HitFilter* filter = nullptr;  ///< a filtered occlusion query's
};

const QueryContext& query_of(const RTCIntersectContext* context) {
  return *reinterpret_cast<const QueryContext*>(context);
}

/// How much wider than a query's range the segment Embree traverses for user primitives is,
/// relatively, at both ends: Embree's box tests round by a few ulps, and a box that ends
/// exactly where a hit lies (a triangle in an axis plane) would otherwise be culled now and
/// then. The callbacks test primitives with the query's own range.
constexpr float kWiden = 1e-5f;

/// The segment Embree traverses for a query of `t_range`: widened by kWiden with user
/// primitives only; with native triangles the range itself, but for the smallest normal float
/// for 0: Embree includes tnear, and mjray's range is open at 0 (no hits on the origin's own
/// surface).
RTCRay embree_ray(const Ray& ray, Interval t_range, bool native_triangles) {
  RTCRay r{};
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  if (native_triangles) {
    r.tnear = std::max(FLT_MIN, t_range.min);
    r.tfar = t_range.max;
  } else {
    r.tnear = std::max(0.f, t_range.min * (1 - kWiden));
    r.tfar = t_range.max * (1 + kWiden);
  }
  r.mask = ~0u;
  r.flags = 0;
  return r;
}

// Embree leaves rays with NaN or infinite components undefined; mjray says "no hit".
bool valid_query(const Ray& ray, Interval t_range) {
  return t_range.max > t_range.min && is_finite(ray.origin) && is_finite(ray.direction);
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
  const auto& user = *static_cast<const UserPrimitives*>(args->geometryUserPtr);
  const Bounds3 b = user.prims->primitive_bounds(user.first + args->primID);
  *args->bounds_o = {b.lo.x, b.lo.y, b.lo.z, 0, b.hi.x, b.hi.y, b.hi.z, 0};
}

Ray ray_of(RTCRayN* ray, unsigned n, unsigned i) {
  return {{RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)},
          {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)}};
}

void user_intersect(const RTCIntersectFunctionNArguments* args) {
  const auto& user = *static_cast<const UserPrimitives*>(args->geometryUserPtr);
  const Interval query = query_of(args->context).t_range;
  const uint32_t prim = user.first + args->primID;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    // Brute force's answer whatever order Embree visits primitives in: once a hit is held (its
    // t in Ng.x, which shading never reads), only a nearer one, or one at the same t with a
    // lower id, replaces it. The range reaches a float past the held t, as a triangle's range
    // test, made before its division, may round either way there.
    const unsigned held_geometry = RTCHitN_geomID(hits, args->N, i);
    const bool holding = held_geometry != RTC_INVALID_GEOMETRY_ID;
    const float held_t = !holding                         ? query.max
                         : held_geometry == kUserGeometry ? RTCHitN_Ng_x(hits, args->N, i)
                                                          : RTCRayN_tfar(rays, args->N, i);  // a native triangle's
    const Interval reach{query.min, holding ? next_float(held_t, true) : query.max};
    const auto hit = user.prims->intersect(prim, ray_of(rays, args->N, i), reach);
    if (!hit) continue;
    if (holding) {
      const uint32_t held = RTCHitN_primID(hits, args->N, i) + (held_geometry == kUserGeometry ? user.first : 0);
      if (!(hit->t < held_t || (hit->t == held_t && prim < held))) continue;
    }
    // Native triangles are ordered by Embree's own t, so beside them the segment ends at the hit.
    const float reach_on = user.native_triangles() ? hit->t : hit->t * (1 + kWiden);
    RTCRayN_tfar(rays, args->N, i) = std::min(RTCRayN_tfar(rays, args->N, i), reach_on);
    RTCHitN_u(hits, args->N, i) = hit->u;
    RTCHitN_v(hits, args->N, i) = hit->v;
    RTCHitN_Ng_x(hits, args->N, i) = hit->t;
    RTCHitN_Ng_y(hits, args->N, i) = 0;
    RTCHitN_Ng_z(hits, args->N, i) = 0;
    RTCHitN_primID(hits, args->N, i) = args->primID;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
  }
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
  const auto& user = *static_cast<const UserPrimitives*>(args->geometryUserPtr);
  const QueryContext& query = query_of(args->context);
  const uint32_t prim = user.first + args->primID;
  const bool filtered = query.filter && user.prims->filtered(prim, query.filter->sees_opaque);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    const auto hit = user.prims->intersect(prim, ray_of(args->ray, args->N, i), query.t_range);
    if (!hit) continue;
    if (filtered && !query.filter->blocks(*hit)) continue;
    RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;  // Embree's "occluded" mark
  }
}

/// The context filter of filtered occlusion queries, for native triangles (user primitives
/// decide in their own callback): the filter sees the hit as mjray's own test computes it, and
/// a hit that test does not confirm is passed over; rejecting a hit (valid = 0) lets the ray go on.
void triangle_occlusion_filter(const RTCFilterFunctionNArguments* args) {
  const QueryContext& query = query_of(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1 || RTCHitN_geomID(args->hit, args->N, i) != kTriangleGeometry) continue;
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
    if (!query.prims->filtered(prim, query.filter->sees_opaque)) continue;
    const auto exact = query.prims->intersect(prim, ray_of(args->ray, args->N, i), query.t_range);
    if (!exact || !query.filter->blocks(*exact)) args->valid[i] = 0;
  }
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(const PrimitiveSet& prims, int threads, bool exact_hits, bool robust)
    : prims_(prims), bounds_(prims.bounds()) {
  // Create the device, counting every byte it allocates.
  const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw SceneError("embree: cannot create a device (" + error_text(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceMemoryMonitorFunction(device_, count_device_bytes, &device_bytes_);
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  // Robust mode makes Embree's box tests conservative, as exact hits need, and its native
  // triangle test watertight, as mjray's own (Woop et al.) is; filtered occlusion queries
  // need the context filter.
  const int robust_flag = robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
  rtcSetSceneFlags(scene_, RTCSceneFlags(robust_flag | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));

  // With exact hits every primitive is a user primitive tested by mjray's own code, so that
  // Embree only traverses and the nearest hit is the one every other accelerator finds: its
  // own triangle test, though watertight too, rounds differently and may order two hits an ulp
  // apart the other way, or miss a triangle at an edge that mjray's test hits. Without, the
  // triangles are Embree's native geometry (one, over the world-space vertices, in primitive
  // order) and only the shapes are user primitives.
  const bool native_triangles = !exact_hits && !prims.triangles.empty();
  if (native_triangles) {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), prims.vertices.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), prims.triangles.size()));
    if (vertices && indices) {
      for (size_t v = 0; v < prims.vertices.size(); ++v) {
        const Point3& p = prims.vertices[v];
        vertices[3 * v] = p.x, vertices[3 * v + 1] = p.y, vertices[3 * v + 2] = p.z;
      }
      for (size_t t = 0; t < prims.triangles.size(); ++t)
        for (size_t k = 0; k < 3; ++k) indices[3 * t + k] = prims.triangles[t][k];
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene_, geometry, kTriangleGeometry);
    rtcReleaseGeometry(geometry);
  }

  user_ = {&prims, native_triangles ? uint32_t(prims.triangles.size()) : 0};
  if (const size_t count = prims.size() - user_.first; count > 0) {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(count));
    rtcSetGeometryUserData(geometry, &user_);
    rtcSetGeometryBoundsFunction(geometry, user_bounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, user_intersect);
    rtcSetGeometryOccludedFunction(geometry, user_occluded);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene_, geometry, kUserGeometry);
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

std::optional<Hit> EmbreeAccelerator::intersect(const Ray& ray, Interval t_range) const {
  if (!valid_query(ray, t_range)) return std::nullopt;
  QueryContext context{{}, &prims_, t_range};
  rtcInitIntersectContext(&context.embree);
  RTCRayHit rayhit;
  rayhit.ray = embree_ray(ray, t_range, user_.native_triangles());
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context.embree, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  // A user primitive's callback set t (in Ng.x), u and v from mjray's own test; a native
  // triangle's are Embree's.
  if (rayhit.hit.geomID == kUserGeometry)
    return Hit{rayhit.hit.Ng_x, user_.first + rayhit.hit.primID, rayhit.hit.u, rayhit.hit.v};
  return Hit{rayhit.ray.tfar, rayhit.hit.primID, rayhit.hit.u, rayhit.hit.v};
}

bool EmbreeAccelerator::occluded(const Ray& ray, float t_max) const {
  const Interval t_range{0, t_max};
  if (!valid_query(ray, t_range)) return false;
  QueryContext context{{}, &prims_, t_range};
  rtcInitIntersectContext(&context.embree);
  RTCRay r = embree_ray(ray, t_range, user_.native_triangles());
  rtcOccluded1(scene_, &context.embree, &r);
  return r.tfar < 0;
}

bool EmbreeAccelerator::occluded(const Ray& ray, Interval t_range, HitFilter& filter) const {
  if (!valid_query(ray, t_range)) return false;
  QueryContext context{{}, &prims_, t_range, &filter};
  rtcInitIntersectContext(&context.embree);
  if (user_.native_triangles() && (prims_.any_transmissive() || filter.sees_opaque))
    context.embree.filter = triangle_occlusion_filter;
  RTCRay r = embree_ray(ray, t_range, user_.native_triangles());
  rtcOccluded1(scene_, &context.embree, &r);
  return r.tfar < 0;
}

}  // namespace mjray
