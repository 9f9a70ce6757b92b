// The baked turbulence grid (noise/turbulence_grid.h): interpolated multilinearly, as the GPU's
// texture filter does, it gives the reference turbulence at any point -- not only at the
// texels it was baked at -- within its 16-bit storage's rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "marble/noise/marble_pattern.h"
#include "marble/noise/turbulence_grid.h"

namespace marble {
namespace {

constexpr float kUnorm16HalfStep = 0.5f / 65535.0f;

// GL_REPEAT + GL_LINEAR on the grid at texel coordinate q (texel i holds the value at q = i).
float sampleGrid(const std::vector<uint16_t>& grid, int w, int dims, glm::vec3 q) {
  const glm::vec3 i = glm::floor(q), f = q - i;
  auto at = [&](int x, int y, int z) {
    auto wrap = [w](int v) { return ((v % w) + w) % w; };
    const size_t index = dims == 3 ? (static_cast<size_t>(wrap(z)) * w + wrap(y)) * w + wrap(x)
                                   : static_cast<size_t>(wrap(y)) * w + wrap(x);
    return grid[index] / 65535.0;
  };
  double v = 0.0;
  for (int corner = 0; corner < (dims == 3 ? 8 : 4); ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
    const double weight = (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y) * (dims == 3 ? (dz ? f.z : 1.0 - f.z) : 1.0);
    v += weight * at(static_cast<int>(i.x) + dx, static_cast<int>(i.y) + dy, static_cast<int>(i.z) + dz);
  }
  return static_cast<float>(v);
}

// Largest difference between the interpolated grid and the reference at random points of
// [-2W, 2W]^n (several periods, negative coordinates included).
float worstDifference(const Material& m, int points) {
  const int dims = turbulenceGridDimensions(m);
  const std::vector<uint16_t> grid = bakeTurbulenceGrid(m);
  EXPECT_EQ(grid.size(), static_cast<size_t>(std::pow(m.resolution, dims)));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-2.0f * m.resolution, 2.0f * m.resolution);
  float worst = 0.0f;
  for (int k = 0; k < points; ++k) {
    const glm::vec3 q(u(rng), u(rng), dims == 3 ? u(rng) : 0.0f);
    const float reference = dims == 3 ? turbulence3(m, q) : turbulence(m, glm::vec2(q));
    worst = std::max(worst, std::fabs(sampleGrid(grid, m.resolution, dims, q) - reference));
  }
  return worst;
}

TEST(TurbulenceGrid, SolidGridInterpolatesToTheReferenceEverywhere) {
  Material m;
  m.mapping = PatternMapping::Solid;
  m.resolution = 64;
  m.turb_size = 16.0f;
  m.seed = 0x5eedu;
  ASSERT_EQ(turbulenceGridDimensions(m), 3);
  EXPECT_LT(worstDifference(m, 20000), kUnorm16HalfStep + 1e-6f);
}

TEST(TurbulenceGrid, PlanarGridInterpolatesToTheReferenceEverywhere) {
  Material m;  // the paper's resolution and octaves
  m.mapping = PatternMapping::Planar;
  ASSERT_EQ(turbulenceGridDimensions(m), 2);
  EXPECT_LT(worstDifference(m, 20000), kUnorm16HalfStep + 1e-6f);
  m.mapping = PatternMapping::Triplanar;
  m.turb_size = 1.0f;  // one octave: the white noise itself, interpolated
  m.resolution = 8;
  ASSERT_EQ(turbulenceGridDimensions(m), 2);
  EXPECT_LT(worstDifference(m, 5000), kUnorm16HalfStep + 1e-6f);
}

// The vein models' grid (issue 16): (W/2)^3 texels 2 texel points apart, four samples each.
// Channel k interpolated at q / 2 must give the vein turbulence at q + offset(k) anywhere.
TEST(TurbulenceGrid, VeinGridInterpolatesToTheFourSamplesEverywhere) {
  Material m;
  m.vein_model = VeinModel::Network;
  m.resolution = 64;
  m.turb_size = 16.0f;
  m.seed = 0x5eedu;
  ASSERT_EQ(turbulenceGridDimensions(m), 3);
  const int n = turbulenceGridSize(m);
  ASSERT_EQ(n, 32);
  ASSERT_EQ(turbulenceGridChannels(m), 4);
  const std::vector<uint16_t> grid = bakeTurbulenceGrid(m);
  ASSERT_EQ(grid.size(), static_cast<size_t>(n) * n * n * 4);
  std::vector<std::vector<uint16_t>> channel(4, std::vector<uint16_t>(static_cast<size_t>(n) * n * n));
  for (size_t i = 0; i < channel[0].size(); ++i)
    for (int k = 0; k < 4; ++k) channel[static_cast<size_t>(k)][i] = grid[i * 4 + static_cast<size_t>(k)];
  Material paper = m;
  paper.vein_model = VeinModel::Paper;
  std::vector<uint16_t> fullOctaves(channel[0].size());
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        fullOctaves[(static_cast<size_t>(z) * n + y) * n + x] = static_cast<uint16_t>(
            std::lround(turbulence3(paper, glm::vec3(2 * x, 2 * y, 2 * z)) * 65535.0f));
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-2.0f * m.resolution, 2.0f * m.resolution);
  float worst = 0.0f, worstFullOctaves = 0.0f;
  for (int j = 0; j < 4000; ++j) {
    const glm::vec3 q(u(rng), u(rng), u(rng));
    for (int k = 0; k < 4; ++k) {
      const glm::vec3 p = q + veinSampleOffset(m, k);
      float reference = 0.0f;
      veinTurbulenceRow(m, &p.x, p.y, p.z, 1, &reference);
      worst = std::max(worst, std::fabs(sampleGrid(channel[static_cast<size_t>(k)], n, 3, q * 0.5f) - reference));
    }
    // Negative control: the paper's turbulence (down to 1 texel) is not multilinear on 2-texel
    // cells, so the same construction does not reproduce it between the grid's texels.
    worstFullOctaves = std::max(worstFullOctaves, std::fabs(sampleGrid(fullOctaves, n, 3, q * 0.5f) - turbulence3(paper, q)));
  }
  EXPECT_LT(worst, kUnorm16HalfStep + 1e-6f);
  EXPECT_GT(worstFullOctaves, 100.0f * kUnorm16HalfStep);
  // Offsets are even texel points, so texel i of channel k is the sample at 2i + offset(k).
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 o = veinSampleOffset(m, k);
    for (float c : {o.x, o.y, o.z}) EXPECT_EQ(std::fmod(c, 2.0f), 0.0f) << k;
  }
  Material one = m;
  one.turb_size = 1.0f;  // no octave of 2 texels: no vein grid
  EXPECT_EQ(turbulenceGridDimensions(one), 0);
  EXPECT_FALSE(turbulenceGridKey(m) == turbulenceGridKey(paper));
}

TEST(TurbulenceGrid, OnlyExactCasesAreBaked) {
  Material m;
  m.mapping = PatternMapping::Solid;
  EXPECT_EQ(turbulenceGridDimensions(m), 3);
  Material perlin = m;
  perlin.basis = NoiseBasis::Perlin;  // the fade curve is not multilinear
  EXPECT_EQ(turbulenceGridDimensions(perlin), 0);
  Material notPowerOfTwo = m;
  notPowerOfTwo.turb_size = 24.0f;  // octaves of 1.5 texels
  EXPECT_EQ(turbulenceGridDimensions(notPowerOfTwo), 0);
  Material fractional = m;
  fractional.turb_size = 0.5f;
  EXPECT_EQ(turbulenceGridDimensions(fractional), 0);
  Material notDividing = m;
  notDividing.resolution = 100;  // 32 does not divide it: the octave's lattice does not wrap at W
  EXPECT_EQ(turbulenceGridDimensions(notDividing), 0);
  Material tooLarge = m;
  tooLarge.resolution = 512;  // 256 MiB
  EXPECT_EQ(turbulenceGridDimensions(tooLarge), 0);
  tooLarge.mapping = PatternMapping::Planar;  // 512^2 is small
  EXPECT_EQ(turbulenceGridDimensions(tooLarge), 2);
  EXPECT_THROW(bakeTurbulenceGrid(perlin), std::logic_error);
}

TEST(TurbulenceGrid, KeyChangesOnlyWithWhatTheGridDependsOn) {
  Material a;
  Material b = a;
  b.turb_power = 9.0f;  // applied after the turbulence
  b.vein_color = {0, 0, 1};
  b.pattern_scale = 3.0f;
  EXPECT_EQ(turbulenceGridKey(a), turbulenceGridKey(b));
  b.seed = a.seed + 1;
  EXPECT_NE(turbulenceGridKey(a), turbulenceGridKey(b));
}

}  // namespace
}  // namespace marble

namespace marble {
namespace {

// AlbedoSampler (`marble bake`'s pattern): with its grid, the colour at arbitrary surface
// points is marbleAlbedo's up to the grid's rounding; without (too few points to pay for the
// grid), it is marbleAlbedo exactly.
struct SamplerAgreement {
  float worstLinear = 0;
  int differentBytes = 0;  // sRGB 8-bit channels that differ by more than one level
};
SamplerAgreement compareSampler(const AlbedoSampler& sampler, const Material& reference, int points) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  auto byte = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return std::lround((c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f) * 255.0f);
  };
  SamplerAgreement a;
  for (int k = 0; k < points; ++k) {
    const glm::vec3 p(u(rng), u(rng), u(rng)), n = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0, 0, 2));
    const glm::vec3 got = sampler(p, n), want = marbleAlbedo(reference, p, n);
    for (int c = 0; c < 3; ++c) {
      a.worstLinear = std::max(a.worstLinear, std::fabs(got[c] - want[c]));
      if (std::abs(byte(got[c]) - byte(want[c])) > 1) ++a.differentBytes;
    }
  }
  return a;
}

Material smallGridStone(VeinModel model) {
  Material m = Material{};
  m.mapping = PatternMapping::Solid;
  m.vein_model = model;
  m.resolution = 64;
  m.turb_size = 16.0f;
  return m;
}

TEST(AlbedoSampler, GridColoursAreThePerPointColours) {
  for (VeinModel model : {VeinModel::Paper, VeinModel::Network}) {
    const Material m = smallGridStone(model);
    const AlbedoSampler sampler(m, 1e9);
    ASSERT_TRUE(sampler.usesGrid());
    const SamplerAgreement a = compareSampler(sampler, m, 20000);
    // The vein network's edges are steep: a turbulence off by 1e-5 moves an edge by ~1e-5 of
    // the warp, which rounds one point in thousands to the next level but never further.
    EXPECT_LT(a.worstLinear, 2e-3f) << static_cast<int>(model);
    EXPECT_EQ(a.differentBytes, 0) << static_cast<int>(model);
    // Negative control: another seed's grid is far from this stone.
    Material other = m;
    other.seed += 1;
    EXPECT_GT(compareSampler(AlbedoSampler(other, 1e9), m, 2000).differentBytes, 100) << static_cast<int>(model);
  }
}

TEST(AlbedoSampler, FewPointsOrInexactGridsEvaluatePerPoint) {
  const Material m = smallGridStone(VeinModel::Network);
  const AlbedoSampler few(m, 100.0);  // 64^3 / 4 turbulences would cost more than 400
  EXPECT_FALSE(few.usesGrid());
  EXPECT_EQ(compareSampler(few, m, 500).worstLinear, 0.0f);
  Material perlin = m;
  perlin.basis = NoiseBasis::Perlin;  // its fade curve is not multilinear: no exact grid
  EXPECT_FALSE(AlbedoSampler(perlin, 1e9).usesGrid());
}

}  // namespace
}  // namespace marble
