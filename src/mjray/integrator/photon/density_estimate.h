#pragma once
/// Irradiance from the photons near a surface point.

#include <span>

#include "mjray/core/color.h"
#include "mjray/integrator/photon/kd_tree.h"
#include "mjray/integrator/photon/photon.h"

namespace mjray {

/// How many photons an estimate gathers and from how far.
struct DensityQuery {
  int neighbours = 64;      ///< k of the k-nearest estimate
  float max_radius = 1;     ///< photons beyond this never count
};

/// The photons of one estimate at most (the scratch space queries use).
inline constexpr int kMaxNeighbours = 256;

/// Whether a stored point lies on a surface facing the way of n (cos > 0.8 between the
/// normals): photons on the far side of a thin wall or around a corner do not count.
inline bool faces_alike(const PackedNormal& stored, const Normal3& n) { return stored.dot(n) > 0.8f; }

/// The irradiance at p (unit normal n) from the k nearest photons facing alike, through a
/// cone filter (Jensen: weight 1 − d / (κ·r), κ = 1.1, normalised over the disc) that keeps
/// the edges of caustics sharp; the disc is the k-th photon's, or max_radius when fewer lie
/// within it. Black without photons.
Color irradiance_estimate(const KdTree<Photon>& map, const Point3& p, const Normal3& n, const DensityQuery& query);

}  // namespace mjray
