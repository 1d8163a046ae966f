// What materials answer: specular lobes and their weights, the light shadow rays keep through
// each material, and the physically based BRDF of the Phong terms.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "mjray/core/rng.h"
#include "mjray/material/material.h"

namespace mjray {
namespace {

/// A frame at a surface facing +z, viewed from direction `wo` (unit).
ShadingFrame frame(const Vector3& wo, bool outside = true) {
  const Normal3 ng = outside ? Normal3(0, 0, 1) : Normal3(0, 0, -1);
  return {wo, face_forward(Normal3(0, 0, 1), wo), ng};
}

const PhongMaterial kBlack{{0, 0, 0}, {0, 0, 0}, 1};

TEST(MaterialLobes, PhongHasNoneAndIsOpaque) {
  const ShadingFrame f = frame({0, 0, 1});
  EXPECT_TRUE(specular_lobes(Material(kBlack), f).empty());
  EXPECT_EQ(shadow_transmittance(Material(kBlack), f), Color(0, 0, 0));
  EXPECT_EQ(shadow_transmittance(Material(ReflectiveMaterial{kBlack, 0.5f}), f), Color(0, 0, 0));
  EXPECT_EQ(shadow_transmittance(Material(GlossyMaterial{kBlack, 0.5f, 8}), f), Color(0, 0, 0));
}

TEST(MaterialLobes, MirrorReflectsAboutTheNormalWithItsReflectivity) {
  const Vector3 wo = normalize(Vector3(0.3f, -0.4f, 0.8f));
  const SpecularLobes lobes = specular_lobes(Material(ReflectiveMaterial{kBlack, 0.7f}), frame(wo));
  ASSERT_EQ(lobes.end() - lobes.begin(), 1);
  const SpecularLobe& lobe = *lobes.begin();
  EXPECT_EQ(lobe.kind, LobeKind::kReflection);
  EXPECT_FLOAT_EQ(lobe.weight, 0.7f);
  EXPECT_NEAR(lobe.direction.x, -wo.x, 1e-6f);
  EXPECT_NEAR(lobe.direction.y, -wo.y, 1e-6f);
  EXPECT_NEAR(lobe.direction.z, wo.z, 1e-6f);
  // Zero reflectivity: no lobe to trace.
  EXPECT_TRUE(specular_lobes(Material(ReflectiveMaterial{kBlack, 0}), frame(wo)).empty());
}

TEST(MaterialLobes, DielectricSplitsIntoReflectedAndRefractedShares) {
  const Vector3 wo = normalize(Vector3(0.5f, 0, 1));
  const FresnelMaterial glass{kBlack, 1, 1.5f};
  const SpecularLobes lobes = specular_lobes(Material(glass), frame(wo));
  ASSERT_EQ(lobes.end() - lobes.begin(), 2);
  const SpecularLobe& reflected = lobes.begin()[0];
  const SpecularLobe& refracted = lobes.begin()[1];
  EXPECT_EQ(reflected.kind, LobeKind::kReflection);
  EXPECT_EQ(refracted.kind, LobeKind::kTransmission);
  EXPECT_FLOAT_EQ(reflected.weight, fresnel_dielectric(wo.z, 1, 1.5f));
  EXPECT_FLOAT_EQ(reflected.weight + refracted.weight, 1);
  // Snell: sin θt = sin θi / 1.5, going into the surface.
  EXPECT_NEAR(std::hypot(refracted.direction.x, refracted.direction.y), std::sqrt(1 - wo.z * wo.z) / 1.5f, 1e-6f);
  EXPECT_LT(refracted.direction.z, 0);
}

TEST(MaterialLobes, TotalInternalReflectionReflectsEverything) {
  // From inside glass at 60° from the normal, past the critical angle asin(1/1.5) ≈ 41.8°.
  const Vector3 wo = normalize(Vector3(std::sin(1.047f), 0, -std::cos(1.047f)));
  for (const Material& m : {Material(FresnelMaterial{kBlack, 1, 1.5f}), Material(RefractiveMaterial{kBlack, 0.2f, 1, 1.5f})}) {
    const ShadingFrame inside{wo, Normal3(0, 0, -1), Normal3(0, 0, 1)};
    const SpecularLobes lobes = specular_lobes(m, inside);
    ASSERT_EQ(lobes.end() - lobes.begin(), 1);
    EXPECT_EQ(lobes.begin()->kind, LobeKind::kReflection);
    EXPECT_FLOAT_EQ(lobes.begin()->weight, 1);
  }
  // A shadow ray does not bend: leaving at 60° it keeps what entering at 60° keeps.
  const ShadingFrame inside{wo, Normal3(0, 0, -1), Normal3(0, 0, 1)};
  EXPECT_FLOAT_EQ(shadow_transmittance(Material(FresnelMaterial{kBlack, 1, 1.5f}), inside).r,
                  1 - fresnel_dielectric(std::cos(1.047f), 1, 1.5f));
}

TEST(MaterialShadows, TransmissiveMaterialsPassTheRefractedShare) {
  for (const float cos_i : {1.f, 0.8f, 0.3f}) {
    const Vector3 wo(std::sqrt(1 - cos_i * cos_i), 0, cos_i);
    const ShadingFrame f = frame(wo);
    EXPECT_EQ(shadow_transmittance(Material(RefractiveMaterial{kBlack, 0, 1, 1.5f}), f), Color(1, 1, 1));
    EXPECT_FLOAT_EQ(shadow_transmittance(Material(RefractiveMaterial{kBlack, 0.25f, 1, 1.5f}), f).g, 0.75f);
    EXPECT_FLOAT_EQ(shadow_transmittance(Material(FresnelMaterial{kBlack, 1, 1.5f}), f).b,
                    1 - fresnel_dielectric(cos_i, 1, 1.5f));
  }
  // At normal incidence, F = ((1 − 1.5)/(1 + 1.5))² = 0.04.
  EXPECT_NEAR(shadow_transmittance(Material(FresnelMaterial{kBlack, 1, 1.5f}), frame({0, 0, 1})).r, 0.96f, 1e-6f);
}

TEST(MaterialBrdf, LambertianPartReflectsItsAlbedo) {
  // With density cos θ / π, every sample's weight f·cos θ / pdf is the albedo kd of the
  // diffuse part (ks = 0), so ∫ f cos θ dω = kd.
  const LocalShading diffuse{{0.8f, 0.5f, 0.2f}, {0, 0, 0}, 1};
  const ShadingFrame f = frame(normalize(Vector3(0.2f, 0.1f, 1)));
  RandomStream random(3, 0, 0);
  for (int i = 0; i < 2000; ++i) {
    const auto s = diffuse.sample(f, random.uniform(), random.uniform());
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->pdf, dot(s->wi, f.n) / std::numbers::pi_v<float>, 1e-5f);
    const Color weight = s->f * (dot(s->wi, f.n) / s->pdf);
    EXPECT_NEAR(weight.r, 0.8f, 1e-5f);
    EXPECT_NEAR(weight.b, 0.2f, 1e-5f);
  }
}

TEST(MaterialBrdf, NormalisedPhongLobeConservesEnergyAtNormalIncidence) {
  // Viewed along n, the lobe (s + 2)/2π · cos^s α integrates with cos θ to 1 (α = θ there).
  const LocalShading glossy{{0, 0, 0}, {1, 1, 1}, 20};
  const ShadingFrame f = frame({0, 0, 1});
  double integral = 0;
  constexpr int kRings = 2000;
  for (int i = 0; i < kRings; ++i) {
    const double theta = (i + 0.5) / kRings * std::numbers::pi / 2;
    const Vector3 wi(float(std::sin(theta)), 0, float(std::cos(theta)));
    integral += glossy.eval(f, wi).r * std::cos(theta) * std::sin(theta) * 2 * std::numbers::pi *
                (std::numbers::pi / 2 / kRings);
  }
  EXPECT_NEAR(integral, 1, 1e-3);
  EXPECT_EQ(glossy.eval(f, {0, 0, -1}), Color(0, 0, 0));  // below the surface
}

}  // namespace
}  // namespace mjray
