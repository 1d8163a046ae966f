#include "mjray/integrator/photon/photon_emission.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mjray/core/sampling.h"
#include "mjray/material/material.h"

namespace mjray {

namespace {

constexpr size_t kMaxTargets = 32;
constexpr float kTwoPi = 2 * std::numbers::pi_v<float>;

/// The directions from a point that reach a ball: a cone stored as its axis and 1 − cos of
/// its half-angle (kept accurate for the tiny cones of distant lights), or every direction.
struct Cone {
  Vector3 axis{0, 0, 1};
  float one_minus_cos = 2;

  static Cone of(const EmissionCone& c) { return {c.axis, c.one_minus_cos}; }
  static Cone toward(const Point3& from, const BoundingSphere& ball) {
    const Vector3 d = ball.centre - from;
    const float distance = length(d);
    if (!(distance > ball.radius)) return {};
    const float sin2 = (ball.radius / distance) * (ball.radius / distance);
    return {d / distance, sin2 / (1 + std::sqrt(1 - sin2))};
  }
  float solid_angle() const { return kTwoPi * one_minus_cos; }
  bool contains(const Vector3& w) const { return one_minus_cos >= 2 || 1 - dot(w, axis) <= one_minus_cos; }
  /// Whether the two cones share a direction.
  bool overlaps(const Cone& other) const {
    if (one_minus_cos >= 2 || other.one_minus_cos >= 2) return true;
    const auto angle = [](float omc) { return std::acos(std::clamp(1 - omc, -1.f, 1.f)); };
    return std::acos(std::clamp(dot(axis, other.axis), -1.f, 1.f)) <= angle(one_minus_cos) + angle(other.one_minus_cos);
  }
  /// A direction uniform over the cone's solid angle.
  Vector3 sample(float u1, float u2) const {
    const float t = u1 * one_minus_cos;  // 1 − cos θ
    const float sin_theta = std::sqrt(std::max(0.f, t * (2 - t))), phi = kTwoPi * u2;
    const Basis frame = orthonormal_basis(axis);
    return normalize(frame.tangent * (sin_theta * std::cos(phi)) + frame.bitangent * (sin_theta * std::sin(phi)) +
                     axis * (1 - t));
  }
};

/// A ball around a unit shape placed by world_from_object, about its ball's mapped centre:
/// the smaller of two bounds, its ball's radius stretched by the map's largest singular value
/// (bounded by Gershgorin's circles on AᵀA; exact for a sphere under rotation and uniform
/// scale) and the farthest mapped corner of its box (exact for a box).
BoundingSphere world_ball(const BoundingSphere& object, const Bounds3& object_box, const Transform& world_from_object) {
  const Vector3 a[3] = {world_from_object(Vector3(1, 0, 0)), world_from_object(Vector3(0, 1, 0)),
                        world_from_object(Vector3(0, 0, 1))};
  float stretch2 = 0;
  for (const Vector3& row : a)
    stretch2 = std::max(stretch2, std::abs(dot(row, a[0])) + std::abs(dot(row, a[1])) + std::abs(dot(row, a[2])));
  const Point3 centre = world_from_object(object.centre);
  float corner2 = 0;
  for (int i = 0; i < 8; ++i) {
    const Vector3 d = world_from_object(object_box.corner(i)) - centre;
    corner2 = std::max(corner2, dot(d, d));
  }
  return {centre, std::min(object.radius * std::sqrt(stretch2), std::sqrt(corner2)) * 1.0001f};
}

/// The mean of a colour's channels: how much a light's photons weigh in the choice.
float brightness(const Color& c) { return (c.r + c.g + c.b) / 3; }

/// The disc across the sun's light that a ball presents to it.
float cross_section(const BoundingSphere& ball) { return std::numbers::pi_v<float> * ball.radius * ball.radius; }

}  // namespace

std::vector<BoundingSphere> specular_targets(const World& world) {
  std::vector<BoundingSphere> balls;
  Bounds3 all;
  for (const WorldMesh& mesh : world.meshes) {
    if (!specular(world.materials[mesh.material])) continue;
    const uint32_t end = mesh.first_triangle + mesh.triangle_count;
    Bounds3 box;
    for (uint32_t t = mesh.first_triangle; t < end; ++t) box.expand(world.primitives.primitive_bounds(t));
    all.expand(box);
    // The ball about the box's centre through the farthest vertex.
    const Point3 centre = box.centre();
    float radius2 = 0;
    for (uint32_t t = mesh.first_triangle; t < end; ++t)
      for (const Point3& p : world.primitives.triangle_vertices(t)) radius2 = std::max(radius2, dot(p - centre, p - centre));
    balls.push_back({centre, std::sqrt(radius2) * 1.0001f});
  }
  const uint32_t first_shape = uint32_t(world.primitives.triangles.size());
  for (size_t i = 0; i < world.shapes.size(); ++i) {
    if (!specular(world.materials[world.shapes[i].material])) continue;
    const ShapeInstance& instance = world.primitives.shape(first_shape + uint32_t(i));
    const BoundingSphere object = std::visit([](const auto& s) { return s.object_bounding_sphere(); }, instance.shape);
    const Bounds3 box = std::visit([](const auto& s) { return s.object_bounds(); }, instance.shape);
    balls.push_back(world_ball(object, box, world.shapes[i].world_from_object));
    all.expand(instance.world_bounds);
  }
  if (balls.size() > kMaxTargets) return {{all.centre(), length(all.diagonal()) * 0.5f * 1.0001f}};
  return balls;
}

PhotonSource::PhotonSource(const std::vector<Light>& lights) : lights_(lights) {
  for (uint32_t l = 0; l < lights.size(); ++l) choices_.push_back({l, -1, brightness(power(lights[l]))});
  normalise_choices();
}

PhotonSource::PhotonSource(const std::vector<Light>& lights, std::vector<BoundingSphere> targets)
    : lights_(lights), targets_(std::move(targets)) {
  // Each (light, target) in proportion to the light's flux toward the target: from its centre
  // into the target's cone (none where that misses a spot's cone), or the sun's through the
  // target's cross-section.
  for (uint32_t l = 0; l < lights.size(); ++l) {
    for (int t = 0; t < int(targets_.size()); ++t) {
      const BoundingSphere& target = targets_[size_t(t)];
      double share = 0;
      if (const SunLight* sun = distant_light(lights[l])) {
        share = double(brightness(sun->colour)) * cross_section({target.centre, sun->covering_radius(target.radius)});
      } else {
        const EmissionPoint centre = emission_point(lights[l], {0.5f, 0.5f});
        const Cone cone = Cone::toward(centre.position, target);
        if (cone.overlaps(Cone::of(emission_cone(lights[l]))))
          share = double(brightness(centre.intensity)) * cone.solid_angle();
      }
      choices_.push_back({l, t, share});
    }
  }
  normalise_choices();
}

void PhotonSource::normalise_choices() {
  choices_.erase(std::remove_if(choices_.begin(), choices_.end(), [](const Choice& c) { return !(c.probability > 0); }),
                 choices_.end());
  double total = 0;
  for (const Choice& c : choices_) cumulative_.push_back(total += c.probability);
  for (size_t i = 0; i < choices_.size(); ++i) choices_[i].probability /= total, cumulative_[i] /= total;
}

EmittedPhoton PhotonSource::emit(uint64_t index, uint64_t count, RandomStream& random) const {
  const double u = (double(index) + random.uniform()) / double(count);
  const size_t c = std::min(size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin()),
                            choices_.size() - 1);
  const Choice& choice = choices_[c];
  if (const SunLight* sun = distant_light(lights_[choice.light])) return emit_from_sun(*sun, c, count, random);
  const float u1 = random.uniform(), u2 = random.uniform();
  const Light& light = lights_[choice.light];
  const EmissionPoint from = emission_point(light, {u1, u2});
  const auto cone_of = [&](const Choice& k) {
    return k.target < 0 ? Cone::of(emission_cone(light)) : Cone::toward(from.position, targets_[size_t(k.target)]);
  };
  const Cone cone = cone_of(choice);
  const float u3 = random.uniform(), u4 = random.uniform();
  const Vector3 direction = cone.sample(u3, u4);
  // The density of this direction over every choice of the same light (cones may overlap).
  double density = choice.probability / cone.solid_angle();
  for (size_t k = 0; k < choices_.size(); ++k) {
    if (k == c || choices_[k].light != choice.light) continue;
    const Cone other = cone_of(choices_[k]);
    if (other.contains(direction)) density += choices_[k].probability / other.solid_angle();
  }
  return {{from.position, direction}, from.intensity * (emission_profile(light, direction) / float(double(count) * density)),
          choice.light};
}

EmittedPhoton PhotonSource::emit_from_sun(const SunLight& sun, size_t c, uint64_t count, RandomStream& random) const {
  // A point across the disc the choice's ball (a target's, or the scene's) shows the sun, a
  // direction from the sun's disc, and a start beyond the scene on the line through both.
  const Choice& choice = choices_[c];
  const auto ball_of = [&](const Choice& k) {
    const BoundingSphere b = k.target < 0 ? BoundingSphere{sun.scene_centre, sun.scene_radius} : targets_[size_t(k.target)];
    return BoundingSphere{b.centre, sun.covering_radius(b.radius)};  // so tilted lines still cover it
  };
  const BoundingSphere ball = ball_of(choice);
  const float u1 = random.uniform(), u2 = random.uniform();
  const Point2 d = sample_concentric_disk(u1, u2);
  const Basis across = orthonormal_basis(sun.direction);
  const Point3 through = ball.centre + (across.tangent * d.u + across.bitangent * d.v) * ball.radius;
  const float u3 = random.uniform(), u4 = random.uniform();
  const Vector3 direction = -normalize(sun.toward({u3, u4}));
  // The density of this point across the light over every disc of the same light.
  double density = choice.probability / cross_section(ball);
  for (size_t k = 0; k < choices_.size(); ++k) {
    if (k == c || choices_[k].light != choice.light) continue;
    const BoundingSphere other = ball_of(choices_[k]);
    const Vector3 v = through - other.centre;
    const Vector3 off_axis = v - sun.direction * dot(v, sun.direction);
    if (dot(off_axis, off_axis) <= other.radius * other.radius) density += choices_[k].probability / cross_section(other);
  }
  return {{through - direction * sun.clearance(through), direction}, sun.colour / float(double(count) * density),
          choice.light};
}

}  // namespace mjray
