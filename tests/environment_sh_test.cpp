// Diffuse environment light as 9 SH coefficients (src/marble/environment/sh_irradiance.h):
// checked against irradiance known in closed form, and the shader's regrouped polynomial
// against the paper's formula.
#include <gtest/gtest.h>

#include <cmath>

#include "hdr_support.h"
#include "marble/environment/equirect.h"
#include "marble/environment/sh_irradiance.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr float kPi = 3.14159265f;

std::vector<glm::vec3> someNormals() {
  std::vector<glm::vec3> n = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int i = 0; i < 40; ++i) {  // a spiral over the sphere
    const float z = 1.0f - 2.0f * (i + 0.5f) / 40.0f, a = 2.39996323f * static_cast<float>(i);
    const float r = std::sqrt(1.0f - z * z);
    n.emplace_back(r * std::cos(a), z, r * std::sin(a));
  }
  return n;
}

// environment.glsl's env_diffuse(), term for term.
glm::vec3 shaderDiffuse(const std::array<glm::vec3, 9>& k, const glm::vec3& d) {
  return k[0] + k[1] * d.x + k[2] * d.y + k[3] * d.z + k[4] * (d.x * d.y) + k[5] * (d.y * d.z) + k[6] * (d.x * d.z) +
         k[7] * (d.z * d.z) + k[8] * (d.x * d.x - d.y * d.y);
}

}  // namespace

TEST(EnvironmentSh, ConstantRadianceGivesPiTimesIt) {
  const glm::vec3 L(0.7f, 1.3f, 2.0f);
  const ShCoefficients sh = projectSh9(constantImage(256, 128, L));
  const auto terms = shDiffuseTerms(sh);
  for (const glm::vec3& n : someNormals()) {
    const glm::vec3 e = shIrradiance(sh, n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], kPi * L[c], 1e-3f * kPi * L[c]) << "normal " << n.x << " " << n.y << " " << n.z;
    // What env_diffuse returns: irradiance / pi, here L itself.
    const glm::vec3 d = shaderDiffuse(terms, n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(d[c], L[c], 1e-3f * L[c]);
  }
}

TEST(EnvironmentSh, BrightUpperHemisphereGivesTheSkyIrradiance) {
  // Radiance 1 from above the horizon, 0 below: E(n) = pi (1 + cos theta) / 2 exactly, theta the
  // angle from +Y. This E has only l <= 1 terms, so the 9-term fit must reproduce it.
  const ImageRGBF sky = imageFromDirections(512, 256, [](const glm::vec3& d) { return glm::vec3(d.y > 0.0f ? 1.0f : 0.0f); });
  const ShCoefficients sh = projectSh9(sky);
  for (const glm::vec3& n : someNormals()) {
    const float expected = kPi * (1.0f + n.y) / 2.0f;
    EXPECT_NEAR(shIrradiance(sh, n).g, expected, 0.01f) << "normal " << n.x << " " << n.y << " " << n.z;
  }
  EXPECT_NEAR(shIrradiance(sh, {0, 1, 0}).r, kPi, 0.01f);
  EXPECT_NEAR(shIrradiance(sh, {0, -1, 0}).r, 0.0f, 0.01f);
  EXPECT_NEAR(shIrradiance(sh, {1, 0, 0}).r, kPi / 2.0f, 0.01f);
}

TEST(EnvironmentSh, SmallBrightSourceLightsTheSideFacingIt) {
  // A disc of 10 degrees' radius towards +X: E(n) = L Omega max(n.x, 0) for a distant source.
  // The l <= 2 fit is within a few percent of that where the side faces the source (the paper's
  // worst case is exactly this kind of small light; it rings a little on the far side).
  const float cosR = std::cos(glm::radians(10.0f));
  const ImageRGBF img = imageFromDirections(1024, 512, [&](const glm::vec3& d) { return glm::vec3(d.x > cosR ? 100.0f : 0.0f); });
  const float omega = 2.0f * kPi * (1.0f - cosR);
  const ShCoefficients sh = projectSh9(img);
  const float facing = shIrradiance(sh, {1, 0, 0}).r;
  EXPECT_NEAR(facing, 100.0f * omega, 0.1f * 100.0f * omega);
  EXPECT_NEAR(shIrradiance(sh, glm::normalize(glm::vec3(1, 1, 0))).r, 100.0f * omega * 0.7071f, 0.1f * 100.0f * omega);
  EXPECT_LT(std::abs(shIrradiance(sh, {-1, 0, 0}).r), 0.1f * facing);
}

TEST(EnvironmentSh, ShaderPolynomialIsThePapersFormulaOverPi) {
  const ImageRGBF sky = syntheticSky(256);
  const ShCoefficients sh = projectSh9(sky);
  const auto terms = shDiffuseTerms(sh);
  for (const glm::vec3& n : someNormals()) {
    const glm::vec3 a = shIrradiance(sh, n) / kPi, b = shaderDiffuse(terms, n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-4f * std::max(1.0f, std::abs(a[c])));
  }
}
