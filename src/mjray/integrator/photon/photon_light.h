#pragma once
/// Caustics and global illumination from photon maps, at the surfaces Whitted's recursion
/// shades.

#include "mjray/accel/accelerator.h"
#include "mjray/integrator/indirect_light.h"
#include "mjray/integrator/photon/photon_maps.h"
#include "mjray/scene/world.h"

namespace mjray {

/// The caustic map's radiance estimate (kd times the photons' irradiance, as the direct term
/// it replaces), plus, with a global map, a final gather: gather_rays rays drawn by the
/// surface's BRDF, each bringing kd times the irradiance precomputed nearest where it lands
/// (through mirrors and glass first, along one lobe chosen by weight). A gather ray that
/// leaves the scene brings nothing: the background lights nothing, as in Whitted.
class PhotonMappedLight final : public IndirectLight {
 public:
  PhotonMappedLight(const World& world, const Accelerator& accel, const PhotonMaps& maps, const PhotonSettings& settings)
      : world_(world), accel_(accel), maps_(maps), settings_(settings) {}

  Color radiance(const SurfaceInteraction& si, const ShadingFrame& frame, const LocalShading& local, float weight,
                 RandomStream& random, TraceState& state) const override;

 private:
  /// The light arriving at si from other surfaces, by final gathering.
  Color final_gather(const SurfaceInteraction& si, const ShadingFrame& frame, float weight, RandomStream& random,
                     RayCounters& counters) const;
  /// The radiance arriving along a gather ray.
  Color gathered(Ray ray, RandomStream& random, RayCounters& counters) const;
  /// The irradiance sample nearest p facing alike, or black.
  Color stored_irradiance(const Point3& p, const Normal3& n) const;

  const World& world_;
  const Accelerator& accel_;
  const PhotonMaps& maps_;
  PhotonSettings settings_;
};

}  // namespace mjray
