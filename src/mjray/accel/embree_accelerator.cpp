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

// The shapes' user geometry: bounds and hits come from the PrimitiveSet itself.
void shape_bounds(const RTCBoundsFunctionArguments* args) {
  const PrimitiveSet& prims = *static_cast<const PrimitiveSet*>(args->geometryUserPtr);
  const Bounds3 b = prims.primitive_bounds(uint32_t(prims.triangles.size()) + args->primID);
  *args->bounds_o = {b.lo.x, b.lo.y, b.lo.z, 0, b.hi.x, b.hi.y, b.hi.z, 0};
}

// The range a callback's ray asks for (kTNear stands for mjray's open 0).
Interval range_of(RTCRayN* ray, unsigned n, unsigned i) {
  const float t_near = RTCRayN_tnear(ray, n, i);
  return {t_near <= kTNear ? 0 : t_near, RTCRayN_tfar(ray, n, i)};
}

Ray ray_of(RTCRayN* ray, unsigned n, unsigned i) {
  return {{RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)},
          {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)}};
}

void shape_intersect(const RTCIntersectFunctionNArguments* args) {
  const PrimitiveSet& prims = *static_cast<const PrimitiveSet*>(args->geometryUserPtr);
  const uint32_t prim = uint32_t(prims.triangles.size()) + args->primID;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    const auto hit = prims.intersect_shape(prim, ray_of(rays, args->N, i), range_of(rays, args->N, i));
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

/// The context of a filtered occlusion query: Embree's own first, so that callbacks can get
/// back to the rest from the pointer Embree passes them.
struct FilterContext {
  RTCIntersectContext embree;
  const PrimitiveSet* prims;
  HitFilter* filter;
  Interval t_range;  ///< the query's: in a filter call Embree has set the ray's tfar to the hit's t
};

/// Whether the hit of a filtered query on transmissive `prim` blocks: the filter sees the hit
/// as mjray's own test computes it; a hit that test does not confirm is passed over.
bool filtered_blocks(const FilterContext& context, uint32_t prim, const Ray& ray, Interval t_range) {
  const auto exact = context.prims->intersect(prim, ray, t_range);
  return exact && context.filter->blocks(*exact);
}

void shape_occluded(const RTCOccludedFunctionNArguments* args) {
  const PrimitiveSet& prims = *static_cast<const PrimitiveSet*>(args->geometryUserPtr);
  const uint32_t prim = uint32_t(prims.triangles.size()) + args->primID;
  const auto* context = reinterpret_cast<const FilterContext*>(args->context);
  const bool filtered = args->context->filter != nullptr && prims.filtered(prim, context->filter->sees_opaque);
  for (unsigned i = 0; i < args->N; ++i) {
    if (!args->valid[i]) continue;
    const Ray ray = ray_of(args->ray, args->N, i);
    const Interval range = range_of(args->ray, args->N, i);
    const auto hit = prims.intersect_shape(prim, ray, range);
    if (!hit) continue;
    if (filtered && !context->filter->blocks(*hit)) continue;
    RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;  // Embree's "occluded" mark
  }
}

/// The context filter of filtered occlusion queries, for triangles (shapes decide in their
/// own callback): rejecting a hit (valid = 0) lets the ray go on.
void triangle_occlusion_filter(const RTCFilterFunctionNArguments* args) {
  const auto& context = *reinterpret_cast<const FilterContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1 || RTCHitN_geomID(args->hit, args->N, i) != kTriangleGeometry) continue;
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
    if (!context.prims->filtered(prim, context.filter->sees_opaque)) continue;
    if (!filtered_blocks(context, prim, ray_of(args->ray, args->N, i), context.t_range)) args->valid[i] = 0;
  }
}

RTCRay embree_ray(const Ray& ray, Interval t_range) {
  RTCRay r{};
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tnear = std::max(kTNear, t_range.min);
  r.tfar = t_range.max;
  r.mask = ~0u;
  r.flags = 0;
  return r;
}

// Embree leaves rays with NaN or infinite components undefined; mjray says "no hit".
bool valid_query(const Ray& ray, float t_max) {
  return t_max > kTNear && is_finite(ray.origin) && is_finite(ray.direction);
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(const PrimitiveSet& prims, int threads, bool exact_hits, bool robust)
    : prims_(prims), bounds_(prims.bounds()), exact_hits_(exact_hits) {
  // Create the device, counting every byte it allocates.
  const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw SceneError("embree: cannot create a device (" + error_text(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceMemoryMonitorFunction(device_, count_device_bytes, &device_bytes_);
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  // Robust mode makes Embree's triangle test watertight, as mjray's own (Woop et al.) is;
  // filtered occlusion queries need the context filter.
  const int robust_flag = robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
  rtcSetSceneFlags(scene_, RTCSceneFlags(robust_flag | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));

  // Triangles: one geometry over the world-space vertices, in primitive order.
  if (!prims.triangles.empty()) {
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

  // Shapes: one user geometry that defers to the PrimitiveSet.
  if (!prims.shapes.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(prims.shapes.size()));
    rtcSetGeometryUserData(geometry, const_cast<PrimitiveSet*>(&prims));
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

std::optional<Hit> EmbreeAccelerator::intersect(const Ray& ray, Interval t_range) const {
  if (!valid_query(ray, t_range.max)) return std::nullopt;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit;
  rayhit.ray = embree_ray(ray, t_range);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  std::optional<Hit> hit;
  if (rayhit.hit.geomID == kShapeGeometry) {
    hit = Hit{rayhit.ray.tfar, uint32_t(prims_.triangles.size()) + rayhit.hit.primID};
  } else {
    // Recompute the hit with mjray's own watertight test, so that t, u and v (and with them
    // the image) are bit for bit those of every other accelerator. Embree's (u, v) weight
    // vertices 1 and 2 as mjray's (b1, b2) do; they are the fallback should the exact test
    // miss a triangle Embree grazed.
    const uint32_t prim = rayhit.hit.primID;
    if (exact_hits_) hit = prims_.intersect(prim, ray, {t_range.min, kInfinity});
    if (!hit) hit = Hit{rayhit.ray.tfar, prim, rayhit.hit.u, rayhit.hit.v};
  }
  return exact_hits_ ? lowest_at_same_t(ray, *hit) : hit;
}

namespace {

/// Sees every hit at exactly one t and keeps the one of the lowest primitive id.
class SameT final : public HitFilter {
 public:
  explicit SameT(const Hit& first) : HitFilter(true), best(first) {}
  bool blocks(const Hit& hit) override {
    if (hit.t == best.t && hit.prim < best.prim) best = hit;
    return false;
  }
  Hit best;
};

}  // namespace

Hit EmbreeAccelerator::lowest_at_same_t(const Ray& ray, const Hit& hit) const {
  // Embree keeps whichever of several primitives at one t it met first; the others'
  // rule is the lowest id. Look for the others in the one-float window around t.
  SameT same(hit);
  occluded(ray, {next_float(hit.t, false), next_float(hit.t, true)}, same);
  return same.best;
}

bool EmbreeAccelerator::occluded(const Ray& ray, float t_max) const {
  if (!valid_query(ray, t_max)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = embree_ray(ray, {0, t_max});
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0;
}

bool EmbreeAccelerator::occluded(const Ray& ray, Interval t_range, HitFilter& filter) const {
  if (!valid_query(ray, t_range.max)) return false;
  FilterContext context{{}, &prims_, &filter, t_range};
  rtcInitIntersectContext(&context.embree);
  context.embree.filter = prims_.any_transmissive() || filter.sees_opaque ? triangle_occlusion_filter : nullptr;
  RTCRay r = embree_ray(ray, t_range);
  rtcOccluded1(scene_, &context.embree, &r);
  return r.tfar < 0;
}

}  // namespace mjray
