// Reflection, Snell's law and Fresnel reflectance against closed forms.

#include "mjray/material/optics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace mjray {
namespace {

TEST(Optics, FresnelAtNormalIncidenceIsTheSquaredIndexRatio) {
  for (const auto& [n1, n2] : {std::pair{1.f, 1.5f}, {1.5f, 1.f}, {1.f, 1.33f}, {1.2f, 2.4f}}) {
    const float expected = ((n1 - n2) / (n1 + n2)) * ((n1 - n2) / (n1 + n2));
    EXPECT_NEAR(fresnel_dielectric(1, n1, n2), expected, 1e-6f) << n1 << " → " << n2;
  }
}

TEST(Optics, FresnelMatchesTheUnpolarisedFormulaAtOtherAngles) {
  const double n1 = 1, n2 = 1.5;
  for (const double degrees : {10.0, 30.0, 45.0, 56.31, 70.0, 85.0}) {
    const double ti = degrees * M_PI / 180, tt = std::asin(n1 / n2 * std::sin(ti));
    const double rs = std::pow((n1 * std::cos(ti) - n2 * std::cos(tt)) / (n1 * std::cos(ti) + n2 * std::cos(tt)), 2);
    const double rp = std::pow((n2 * std::cos(ti) - n1 * std::cos(tt)) / (n2 * std::cos(ti) + n1 * std::cos(tt)), 2);
    EXPECT_NEAR(fresnel_dielectric(float(std::cos(ti)), 1, 1.5f), (rs + rp) / 2, 2e-6) << degrees;
  }
  // At Brewster's angle the parallel term vanishes: F = r⊥²/2.
  const double brewster = std::atan(1.5);
  EXPECT_LT(fresnel_dielectric(float(std::cos(brewster)), 1, 1.5f), 0.08f);
  EXPECT_FLOAT_EQ(fresnel_dielectric(0, 1, 1.5f), 1);  // grazing
}

TEST(Optics, FresnelIsOneBeyondTheCriticalAngle) {
  const float critical = std::asin(1 / 1.5f);
  EXPECT_LT(fresnel_dielectric(std::cos(critical - 0.01f), 1.5f, 1), 1);
  EXPECT_FLOAT_EQ(fresnel_dielectric(std::cos(critical + 0.01f), 1.5f, 1), 1);
  EXPECT_FLOAT_EQ(fresnel_dielectric(std::cos(1.2f), 1.5f, 1), 1);
}

TEST(Optics, RefractionObeysSnellsLaw) {
  const Normal3 n(0, 1, 0);
  for (const float degrees : {0.f, 15.f, 40.f, 60.f, 80.f}) {
    const float ti = degrees * float(M_PI) / 180;
    const Vector3 wo(std::sin(ti), std::cos(ti), 0);  // toward the viewer, above the surface
    const auto t = refract(wo, n, 1 / 1.5f);
    ASSERT_TRUE(t);
    EXPECT_NEAR(length(*t), 1, 1e-6f);
    EXPECT_LT(t->y, 0);  // goes through
    const float sin_t = std::sqrt(t->x * t->x + t->z * t->z);
    EXPECT_NEAR(1 * std::sin(ti), 1.5f * sin_t, 1e-5f);
    EXPECT_LE(t->x, 0);  // continues to the far side of the normal
  }
  // Leaving glass beyond the critical angle: total internal reflection.
  const float ti = 50 * float(M_PI) / 180;
  EXPECT_FALSE(refract({std::sin(ti), std::cos(ti), 0}, n, 1.5f));
}

TEST(Optics, ReflectionMirrorsAboutTheNormal) {
  const Vector3 r = reflect(normalize(Vector3(1, 2, 0)), Normal3(0, 1, 0));
  EXPECT_NEAR(r.x, -1 / std::sqrt(5.f), 1e-6f);
  EXPECT_NEAR(r.y, 2 / std::sqrt(5.f), 1e-6f);
}

}  // namespace
}  // namespace mjray
