// The marble pattern's C++ reference (paper §3.1): properties that must hold, stage by stage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "marble/noise/marble_pattern.h"

namespace marble {
namespace {

constexpr float kPi = 3.14159265358979f;

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

Material withBasis(NoiseBasis b) {
  Material m;
  m.basis = b;
  return m;
}

class PatternBasisTest : public ::testing::TestWithParam<NoiseBasis> {};
INSTANTIATE_TEST_SUITE_P(Bases, PatternBasisTest, ::testing::Values(NoiseBasis::Value, NoiseBasis::Perlin),
                         [](const auto& info) { return info.param == NoiseBasis::Value ? "value" : "perlin"; });

TEST_P(PatternBasisTest, SameSeedSameBitsOtherSeedOtherValues) {
  Material a = withBasis(GetParam()), b = withBasis(GetParam()), c = withBasis(GetParam());
  c.seed = 2;
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> u(-300.0f, 300.0f);
  int differ = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 q(u(rng), u(rng), u(rng));
    EXPECT_EQ(bits(sinePattern3(a, q)), bits(sinePattern3(b, q)));
    EXPECT_EQ(bits(sinePattern(a, {q.x, q.y})), bits(sinePattern(b, {q.x, q.y})));
    EXPECT_EQ(bits(whiteNoise(a, {q.x, q.y})), bits(whiteNoise(b, {q.x, q.y})));
    differ += turbulence3(a, q) != turbulence3(c, q);
  }
  EXPECT_GT(differ, 490) << "a different seed must give a different lattice";
}

TEST_P(PatternBasisTest, EveryStageStaysInRange) {
  Material m = withBasis(GetParam());
  m.vein2_amount = 0.5f;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1000.0f, 1000.0f);
  for (int i = 0; i < 4000; ++i) {
    const glm::vec3 q(u(rng), u(rng), u(rng));
    const glm::vec2 q2(q.x, q.y);
    const float w = whiteNoise(m, q2), s = smoothNoise(m, q2 / 7.0f), t = turbulence(m, q2), v = sinePattern(m, q2);
    const float s3 = smoothNoise3(m, q / 7.0f), t3 = turbulence3(m, q), v3 = sinePattern3(m, q);
    EXPECT_TRUE(w >= 0.0f && w < 1.0f) << w;
    EXPECT_TRUE(s >= 0.0f && s <= 1.0f) << s;
    EXPECT_TRUE(s3 >= 0.0f && s3 <= 1.0f) << s3;
    EXPECT_TRUE(t >= 0.0f && t < 1.0f) << t;
    EXPECT_TRUE(t3 >= 0.0f && t3 < 1.0f) << t3;
    EXPECT_TRUE(v >= 0.0f && v <= 1.0f) << v;
    EXPECT_TRUE(v3 >= 0.0f && v3 <= 1.0f) << v3;
    const glm::vec3 c = marbleAlbedo(m, q / 500.0f, glm::normalize(glm::vec3(1, 2, 3)));
    for (int k = 0; k < 3; ++k) {
      const float lo = std::min({m.base_color[k], m.vein_color[k], m.vein2_color[k]});
      const float hi = std::max({m.base_color[k], m.vein_color[k], m.vein2_color[k]});
      EXPECT_TRUE(c[k] >= lo - 1e-6f && c[k] <= hi + 1e-6f) << c[k];
    }
  }
}

TEST(PatternTest, WhiteNoiseIsUniformAndPiecewiseConstant) {
  Material m;
  double sum = 0;
  int low = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const float w = whiteNoise(m, {x + 0.25f, y + 0.75f});
      EXPECT_EQ(bits(w), bits(whiteNoise(m, {x + 0.5f, y + 0.125f})));  // one value per cell
      sum += w;
      low += w < 0.25f;
    }
  EXPECT_NEAR(sum / 65536.0, 0.5, 0.01);
  EXPECT_NEAR(low / 65536.0, 0.25, 0.01);
}

TEST(PatternTest, ValueNoiseInterpolatesTheLattice) {
  Material m;
  for (int i = 0; i < 50; ++i) {
    const glm::vec2 cell(static_cast<float>(i * 3), static_cast<float>(i * 7 % 256));
    EXPECT_EQ(smoothNoise(m, cell), whiteNoise(m, cell));  // at lattice points: the white noise
    const float mid = smoothNoise(m, cell + glm::vec2(0.5f, 0.0f));
    EXPECT_NEAR(mid, 0.5f * (whiteNoise(m, cell) + whiteNoise(m, cell + glm::vec2(1, 0))), 1e-6f);
  }
}

TEST(PatternTest, PerlinIsZeroOnTheLatticeAndBounded) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-50.0f, 50.0f);
  float maxAbs = 0.0f;
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    maxAbs = std::max({maxAbs, std::fabs(perlinNoise3(p, 256.0f, 1)), std::fabs(perlinNoise2({p.x, p.y}, 256.0f, 1))});
    EXPECT_EQ(perlinNoise3(glm::floor(p), 256.0f, 1), 0.0f);
  }
  EXPECT_LE(maxAbs, 1.05f);
  EXPECT_GT(maxAbs, 0.5f);
}

TEST(PatternTest, OneOctaveTurbulenceIsHalfTheSmoothNoise) {
  Material m;
  m.turb_size = 1.0f;
  for (int i = 0; i < 100; ++i) {
    const glm::vec2 q(i * 1.37f, i * 2.11f);
    EXPECT_FLOAT_EQ(turbulence(m, q), smoothNoise(m, q) / 2.0f);
  }
}

TEST_P(PatternBasisTest, TurbPowerZeroGivesThePureSine) {
  Material m = withBasis(GetParam());
  m.turb_power = 0.0f;
  const float W = static_cast<float>(m.resolution);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 q(i * 1.7f, i * 0.9f - 40.0f, i * 0.3f);
    const float expect2 = std::fabs(std::sin(kPi * (q.x * m.x_period + q.y * m.y_period) / W));
    EXPECT_NEAR(sinePattern(m, {q.x, q.y}), expect2, 2e-6f);
    const float expect3 = std::fabs(std::sin(kPi * (q.x * m.x_period + q.y * m.y_period + q.z * m.z_period) / W));
    EXPECT_NEAR(sinePattern3(m, q), expect3, 2e-6f);
  }
}

TEST_P(PatternBasisTest, ZeroPeriodsGiveTheTurbulenceAlone) {
  Material m = withBasis(GetParam());
  m.x_period = m.y_period = m.z_period = 0.0f;
  m.turb_power = 1.0f;  // turbulence in [0,1): |sin(pi t)| is then a function of t alone
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 q(i * 1.7f, i * 0.9f - 40.0f, i * 0.3f);
    EXPECT_NEAR(sinePattern(m, {q.x, q.y}), std::fabs(std::sin(kPi * turbulence(m, {q.x, q.y}))), 2e-6f);
    EXPECT_NEAR(sinePattern3(m, q), std::fabs(std::sin(kPi * turbulence3(m, q))), 2e-6f);
  }
}

TEST_P(PatternBasisTest, LatticeAndTurbulenceWrapWithTheTextureWidth) {
  Material m = withBasis(GetParam());
  const float W = static_cast<float>(m.resolution);
  m.x_period = 3.0f;  // whole numbers of periods across the texture: the sine tiles too
  m.y_period = 2.0f;
  m.z_period = 1.0f;
  for (int i = 0; i < 300; ++i) {
    // Dyadic coordinates: adding W is exact, so equal means equal bits.
    const glm::vec3 q(static_cast<float>(i) * 0.8125f, static_cast<float>(i % 37) * 6.5f, static_cast<float>(i % 11) * 3.25f);
    const glm::vec2 q2(q.x, q.y);
    EXPECT_EQ(smoothNoise(m, q2), smoothNoise(m, q2 + glm::vec2(W, 0)));
    EXPECT_EQ(smoothNoise(m, q2), smoothNoise(m, q2 + glm::vec2(0, W)));
    EXPECT_EQ(smoothNoise(m, q2), smoothNoise(m, q2 - glm::vec2(W, W)));
    EXPECT_EQ(turbulence(m, q2), turbulence(m, q2 + glm::vec2(W, 0)));
    EXPECT_EQ(turbulence(m, q2), turbulence(m, q2 + glm::vec2(0, W)));
    EXPECT_EQ(turbulence3(m, q), turbulence3(m, q + glm::vec3(W, 0, 0)));
    EXPECT_EQ(turbulence3(m, q), turbulence3(m, q + glm::vec3(0, W, W)));
    EXPECT_NEAR(sinePattern(m, q2), sinePattern(m, q2 + glm::vec2(W, W)), 1e-5f);
  }
  // And across the wrap the noise is continuous: the last cell blends into the first.
  const float eps = 1.0f / 1024.0f;
  for (int y = 0; y < 64; ++y) {
    const float fy = static_cast<float>(y) + 0.5f;
    EXPECT_NEAR(smoothNoise(m, {W - eps, fy}), smoothNoise(m, {0.0f, fy}), 0.01f);
  }
}

TEST(PatternTest, SolidPatternIsContinuousAcrossSeamsAndIgnoresTheNormal) {
  Material m;  // solid is the default
  ASSERT_EQ(m.mapping, PatternMapping::Solid);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    // A seam: the same position on two faces with different normals (a cube edge, a UV seam).
    const glm::vec3 v1 = marbleAlbedo(m, p, {1, 0, 0}), v2 = marbleAlbedo(m, p, {0, 0, -1});
    EXPECT_EQ(bits(v1.x), bits(v2.x));
    EXPECT_EQ(bits(v1.y), bits(v2.y));
    EXPECT_EQ(bits(v1.z), bits(v2.z));
    // Continuity: a tiny step moves the value a tiny amount (bounded slope).
    const glm::vec3 d(1e-4f, -1e-4f, 1e-4f);
    EXPECT_NEAR(marblePatternValue(m, p, {0, 1, 0}), marblePatternValue(m, p + d, {0, 1, 0}), 0.02f);
  }
}

TEST(PatternTest, PlanarMappingMirrorsLikeThePaper) {
  // s, t come from object x, z (texel = p * W / (2 * scale)); the texture is mirrored
  // (GL_MIRRORED_REPEAT) beyond [0, W]: in object units the mirror planes are x = 0 and
  // x = +-2*scale (and the same for z), and nothing depends on y (the stretch along y).
  Material m;
  m.mapping = PatternMapping::Planar;
  m.pattern_scale = 0.25f;  // the texture spans 0.5 units: the mesh sees it mirrored several times
  const float bound = 2.0f * m.pattern_scale;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const glm::vec3 n(0, 1, 0);
  for (int i = 0; i < 500; ++i) {
    // Dyadic coordinates keep the mirrored texel coordinates exact.
    const float x = std::round(u(rng) * 512.0f) / 512.0f, y = u(rng), z = std::round(u(rng) * 512.0f) / 512.0f;
    const float v = marblePatternValue(m, {x, y, z}, n);
    EXPECT_EQ(v, marblePatternValue(m, {-x, y, z}, n)) << "mirror at x = 0";
    EXPECT_EQ(v, marblePatternValue(m, {x, y, -z}, n)) << "mirror at z = 0";
    EXPECT_EQ(v, marblePatternValue(m, {x, -0.5f * y, z}, n)) << "stretch along y";
    EXPECT_EQ(v, marblePatternValue(m, {x, y, z}, {1, 0, 0})) << "planar ignores the normal";
    const float d = std::fabs(x) * 0.25f;
    EXPECT_EQ(marblePatternValue(m, {bound + d, y, z}, n), marblePatternValue(m, {bound - d, y, z}, n)) << "mirror at the bound";
    EXPECT_EQ(marblePatternValue(m, {x, y, bound + d}, n), marblePatternValue(m, {x, y, bound - d}, n));
  }
  // Inside the bounds it is the 2D texture itself, at texel (x, z) * W / (2 scale).
  const float W = static_cast<float>(m.resolution);
  for (int i = 1; i < 50; ++i) {
    const float x = static_cast<float>(i) / 128.0f, z = static_cast<float>(50 - i) / 128.0f;
    EXPECT_EQ(marblePatternValue(m, {x, 0.3f, z}, n), sinePattern(m, glm::vec2(x, z) * (W / (2.0f * m.pattern_scale))));
  }
  EXPECT_EQ(mirrorTexel(10.0f, 256.0f), 10.0f);
  EXPECT_EQ(mirrorTexel(266.0f, 256.0f), 246.0f);
  EXPECT_EQ(mirrorTexel(-10.0f, 256.0f), 10.0f);
  EXPECT_EQ(mirrorTexel(522.0f, 256.0f), 10.0f);
}

TEST(PatternTest, TriplanarFollowsTheNormal) {
  Material m;
  m.mapping = PatternMapping::Triplanar;
  const float W = static_cast<float>(m.resolution);
  const glm::vec3 p(0.25f, -0.5f, 0.625f);
  const glm::vec3 q = p * (W / 2.0f);
  EXPECT_EQ(marblePatternValue(m, p, {0, 1, 0}), sinePattern(m, {q.x, q.z}));
  EXPECT_EQ(marblePatternValue(m, p, {0, 0, -1}), sinePattern(m, {q.x, q.y}));
  EXPECT_EQ(marblePatternValue(m, p, {1, 0, 0}), sinePattern(m, {q.z, q.y}));
  const float blend = marblePatternValue(m, p, glm::normalize(glm::vec3(1, 1, 0)));
  EXPECT_NEAR(blend, 0.5f * (sinePattern(m, {q.x, q.z}) + sinePattern(m, {q.z, q.y})), 1e-6f);
}

TEST(PatternTest, ColourRampEnds) {
  Material m;
  m.vein_sharpness = 3.0f;
  EXPECT_EQ(patternColor(m, 1.0f), m.base_color);
  EXPECT_EQ(patternColor(m, 0.0f), m.vein_color);
  m.vein2_amount = 1.0f;
  m.vein_sharpness = 1.0f;
  const glm::vec3 mid = patternColor(m, 0.5f);
  EXPECT_NEAR(mid.x, m.vein2_color.x, 1e-6f);
  EXPECT_NEAR(mid.y, m.vein2_color.y, 1e-6f);
  EXPECT_NEAR(mid.z, m.vein2_color.z, 1e-6f);
  // Sharper veins: less of the ramp is vein-coloured.
  Material soft, sharp;
  sharp.vein_sharpness = 4.0f;
  EXPECT_GT(patternColor(sharp, 0.2f).x, patternColor(soft, 0.2f).x);
}

TEST_P(PatternBasisTest, BatchedRowsAreBitIdenticalToThePerPointReference) {
  Material m = withBasis(GetParam());
  m.z_period = 1.5f;
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-400.0f, 400.0f);
  for (int row = 0; row < 20; ++row) {
    const float y = u(rng), z = u(rng), x0 = u(rng);
    const float step = row % 3 == 0 ? 1.0f : (row % 3 == 1 ? 0.37f : 2.5f);
    std::vector<float> xs(300), t2(300), v2(300), t3(300), v3(300);
    for (size_t i = 0; i < xs.size(); ++i) xs[i] = x0 + static_cast<float>(i) * step;
    if (row == 5) std::shuffle(xs.begin(), xs.end(), rng);  // any order is correct
    patternRow2(m, xs.data(), y, 300, t2.data(), v2.data());
    patternRow3(m, xs.data(), y, z, 300, t3.data(), v3.data());
    for (size_t i = 0; i < xs.size(); ++i) {
      ASSERT_EQ(bits(t2[i]), bits(turbulence(m, {xs[i], y}))) << row << " " << i;
      ASSERT_EQ(bits(v2[i]), bits(sinePattern(m, {xs[i], y}))) << row << " " << i;
      ASSERT_EQ(bits(t3[i]), bits(turbulence3(m, {xs[i], y, z}))) << row << " " << i;
      ASSERT_EQ(bits(v3[i]), bits(sinePattern3(m, {xs[i], y, z}))) << row << " " << i;
    }
  }
}

}  // namespace
}  // namespace marble
