// The equirectangular helpers and the GGX prefilter (src/marble/environment/): the mapping's
// conventions, integrals kept by resampling and by every prefiltered level, blur growing with
// the level, and reflections staying where the map has them.
#include <gtest/gtest.h>

#include <cmath>

#include "hdr_support.h"
#include "marble/environment/environment_lighting.h"
#include "marble/environment/equirect.h"
#include "marble/environment/ggx_prefilter.h"

using namespace marble;
using namespace marble::test;

namespace {

void expectNearVec(const glm::vec3& a, const glm::vec3& b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

void expectMeanKept(const glm::dvec3& got, const glm::dvec3& want, double relative, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], relative * want[c]) << what << " channel " << c;
}

// A smooth sky with a broad warm blob: no feature smaller than the coarsest level's texels.
ImageRGBF smoothSky(int width) {
  const glm::vec3 blob = glm::normalize(glm::vec3(0.6f, 0.5f, -0.6f));
  return imageFromDirections(width, width / 2, [&](const glm::vec3& d) {
    const float b = std::exp(8.0f * (glm::dot(d, blob) - 1.0f));
    return glm::vec3(0.3f, 0.4f, 0.6f) * (0.6f + 0.4f * d.y) + glm::vec3(6.0f, 4.0f, 2.0f) * b;
  });
}

// The direction of a level's brightest texel (by green).
glm::vec3 brightest(const ImageRGBF& img) {
  int bx = 0, by = 0;
  float best = -1.0f;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (texelAt(img, x, y).g > best) {
        best = texelAt(img, x, y).g;
        bx = x;
        by = y;
      }
  return equirectDirection((bx + 0.5) / img.width, (by + 0.5) / img.height);
}

}  // namespace

TEST(Equirect, ConventionsMatchTheShader) {
  expectNearVec(equirectDirection(0.5, 0.5), {0, 0, -1}, 1e-6f);  // the image centre looks along -Z
  expectNearVec(equirectDirection(0.75, 0.5), {1, 0, 0}, 1e-6f);  // +X right of it
  expectNearVec(equirectDirection(0.25, 0.5), {-1, 0, 0}, 1e-6f);
  expectNearVec(equirectDirection(0.3, 0.0), {0, 1, 0}, 1e-6f);   // the top row is straight up
  for (double u : {0.1, 0.4, 0.6, 0.9})
    for (double v : {0.05, 0.3, 0.5, 0.8}) {
      const glm::vec2 uv = equirectUv(equirectDirection(u, v));
      EXPECT_NEAR(uv.x, u, 1e-5);
      EXPECT_NEAR(uv.y, v, 1e-5);
    }
  double total = 0;
  for (int y = 0; y < 37; ++y) total += 74 * equirectTexelSolidAngle(y, 74, 37);
  EXPECT_NEAR(total, 4.0 * 3.14159265358979, 1e-9);
}

TEST(Equirect, ResamplingAndMipsKeepTheIntegral) {
  const ImageRGBF sky = syntheticSky(512);  // with a sun 5000x the sky: the hard case
  const glm::dvec3 mean = equirectMean(sky);
  expectMeanKept(equirectMean(resampleEquirect(sky, 128, 64)), mean, 1e-3, "resampled to 128");
  expectMeanKept(equirectMean(resampleEquirect(sky, 300, 150)), mean, 1e-3, "resampled to 300");
  const auto chain = equirectMipChain(sky);
  ASSERT_EQ(chain.size(), 10u);  // 512 x 256 ... 2 x 1, 1 x 1
  EXPECT_EQ(chain.back().width, 1);
  for (size_t i = 1; i + 1 < chain.size(); ++i)
    expectMeanKept(equirectMean(chain[i]), mean, 1e-3, "mip " + std::to_string(i));
}

TEST(GgxPrefilter, LevelsHalveAndTheirAlphaDoubles) {
  EXPECT_EQ(prefilterLevelCount(2048), 9);  // 2048 x 1024 ... 8 x 4
  EXPECT_NEAR(prefilterAlpha1(2048), 8.0f * 3.14159265f / 2048.0f, 1e-7f);
  for (int k = 2; k < 9; ++k) EXPECT_FLOAT_EQ(prefilterAlpha(k, 2048), 2.0f * prefilterAlpha(k - 1, 2048));
  EXPECT_LT(prefilterAlpha(7, 2048), 1.0f);
  EXPECT_GE(prefilterAlpha(8, 2048), 1.0f);  // the last level covers roughness 1
  EXPECT_EQ(prefilterLevelCount(2), 2);      // even the smallest map gets a rough level
  const auto levels = prefilterGgx(smoothSky(256));
  ASSERT_EQ(static_cast<int>(levels.size()), prefilterLevelCount(256));
  for (size_t k = 0; k < levels.size(); ++k) {
    EXPECT_EQ(levels[k].width, 256 >> k);
    EXPECT_EQ(levels[k].height, 128 >> k);
  }
}

TEST(GgxPrefilter, ConstantMapStaysConstant) {
  const glm::vec3 L(0.25f, 1.0f, 3.0f);
  for (const ImageRGBF& level : prefilterGgx(constantImage(128, 64, L)))
    for (int y = 0; y < level.height; ++y)
      for (int x = 0; x < level.width; ++x) expectNearVec(texelAt(level, x, y), L, 1e-5f * 3.0f);
}

TEST(GgxPrefilter, EveryLevelKeepsTheMeanRadiance) {
  // GGX convolution with normalised weights redistributes light without adding or losing any.
  const ImageRGBF smooth = smoothSky(512);
  const glm::dvec3 mean = equirectMean(smooth);
  const auto levels = prefilterGgx(smooth);
  for (size_t k = 0; k < levels.size(); ++k) expectMeanKept(equirectMean(levels[k]), mean, 0.01, "level " + std::to_string(k));
  // With a sun of 1.5 degrees holding two thirds of the light, the coarse levels' few texels
  // sample it less evenly: still within 4%.
  const ImageRGBF sky = syntheticSky(512);
  const glm::dvec3 skyMean = equirectMean(sky);
  const auto skyLevels = prefilterGgx(sky);
  for (size_t k = 0; k < skyLevels.size(); ++k)
    expectMeanKept(equirectMean(skyLevels[k]), skyMean, 0.04, "sun, level " + std::to_string(k));
}

TEST(GgxPrefilter, BlurGrowsWithTheLevelAndReflectionsStayInPlace) {
  const ImageRGBF sky = syntheticSky(512);
  const auto levels = prefilterGgx(sky);
  const glm::vec3 sun = brightest(sky);
  float lastPeak = 1e30f;
  for (size_t k = 1; k < levels.size(); ++k) {
    // The brightest texel of every level is still the sun's direction (within the level's texel
    // and lobe), and it dims as the lobe widens.
    const float angle = std::acos(std::clamp(glm::dot(brightest(levels[k]), sun), -1.0f, 1.0f));
    const float texel = 2.0f * 3.14159265f / static_cast<float>(levels[k].width);
    EXPECT_LT(angle, 1.5f * texel + prefilterAlpha(static_cast<int>(k), 512)) << "level " << k;
    const glm::vec2 uv = equirectUv(sun);
    const float peak = sampleEquirect(levels[k], uv.x, uv.y).g;
    EXPECT_LT(peak, lastPeak) << "level " << k;
    lastPeak = peak;
  }
}

TEST(GgxPrefilter, LobeWidthFollowsGgxAlpha) {
  // A point-like source seen through level k spreads like the GGX lobe of alpha_k: with N = V = R
  // the reflected lobe falls to half its peak about 1.29 alpha from it (D(h) halves at
  // tan(theta_h) = 0.644 alpha, and L turns twice as far as H).
  const glm::vec3 src(0, 0, -1);
  const float cosR = std::cos(glm::radians(0.3f));
  const ImageRGBF img = imageFromDirections(1024, 512, [&](const glm::vec3& d) { return glm::vec3(glm::dot(d, src) > cosR ? 1e4f : 0.0f); });
  const auto levels = prefilterGgx(img);
  for (int k = 2; k <= 5; ++k) {
    const ImageRGBF& level = levels[static_cast<size_t>(k)];
    const float alpha = prefilterAlpha(k, 1024);
    const float peak = sampleEquirect(level, 0.5f, 0.5f).g;
    // Walk right along the equator to half the peak.
    float half = 0;
    for (float a = 0; a < 1.5f; a += 0.0005f)
      if (sampleEquirect(level, 0.5f + a / (2.0f * 3.14159265f), 0.5f).g < 0.5f * peak) {
        half = a;
        break;
      }
    // The footprint filtering widens the narrowest lobes a little; never by half again.
    EXPECT_GT(half, 1.29f * alpha * 0.9f) << "level " << k;
    EXPECT_LT(half, 1.29f * alpha * 1.5f) << "level " << k;
  }
}

TEST(EnvironmentLighting, WideMapsAreAveragedDownForTheGpu) {
  const ImageRGBF sky = syntheticSky(2560);  // 1.25 source texels per texel: fractional coverage
  const PrefilteredEnvironment env = prefilterEnvironment(sky, "sky");
  EXPECT_EQ(env.sourceWidth, 2560);
  EXPECT_EQ(env.levels.front().width, kEnvironmentMaxWidth);
  EXPECT_EQ(env.levels.front().height, kEnvironmentMaxWidth / 2);
  EXPECT_EQ(static_cast<int>(env.levels.size()), prefilterLevelCount(kEnvironmentMaxWidth));
  EXPECT_FLOAT_EQ(env.alpha1, prefilterAlpha1(kEnvironmentMaxWidth));
  expectMeanKept(equirectMean(env.levels.front()), equirectMean(sky), 1e-3, "reduced map");
}
