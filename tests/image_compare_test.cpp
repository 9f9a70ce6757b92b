// The comparison figures of `marble compare` on images whose answer is known.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "marble/core/image_compare.h"

using namespace marble;

namespace {

// A lit disc on exact-zero background: a smooth gradient so SSIM has structure to keep.
CoveredImage disc(int size, float cx, float cy, float radius, float scale = 1.0f) {
  CoveredImage c;
  c.image = ImageRGBF{size, size, std::vector<float>(static_cast<size_t>(size) * size * 3, 0.0f)};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float dx = x - cx, dy = y - cy;
      if (dx * dx + dy * dy > radius * radius) continue;
      float* p = &c.image.pixels[(static_cast<size_t>(y) * size + x) * 3];
      const float v = 0.1f + 0.8f * static_cast<float>(x) / size;
      p[0] = scale * v;
      p[1] = scale * 0.9f * v;
      p[2] = scale * (0.2f + 0.5f * static_cast<float>(y) / size);
    }
  c.coverage = coverageFromValues(c.image);
  return c;
}

}  // namespace

TEST(ImageCompare, IdenticalImagesAgreeCompletely) {
  const CoveredImage a = disc(64, 32, 32, 20);
  const ImageComparison r = compareImages(a, a);
  EXPECT_DOUBLE_EQ(r.iou, 1.0);
  EXPECT_NEAR(r.scale, 1.0, 1e-12);
  EXPECT_NEAR(r.relative_rmse, 0.0, 1e-6);
  EXPECT_NEAR(r.ssim, 1.0, 1e-9);
  EXPECT_EQ(r.ref_pixels, r.joint_pixels);
}

TEST(ImageCompare, ScaleIsRecoveredAndLeavesNoError) {
  const CoveredImage ref = disc(64, 32, 32, 20);
  const CoveredImage test = disc(64, 32, 32, 20, 0.25f);  // the same picture, two stops darker
  const ImageComparison r = compareImages(ref, test);
  EXPECT_DOUBLE_EQ(r.iou, 1.0);
  EXPECT_NEAR(r.scale, 4.0, 1e-5);
  EXPECT_NEAR(r.relative_rmse, 0.0, 1e-3);
  EXPECT_NEAR(r.ssim, 1.0, 1e-4);  // SSIM is taken after the best-fit scale
}

TEST(ImageCompare, NoiseLowersSsimAndRaisesError) {
  const CoveredImage ref = disc(64, 32, 32, 20);
  CoveredImage noisy = ref;
  std::mt19937 rng(7);
  std::normal_distribution<float> n(0.0f, 0.1f);
  for (size_t i = 0; i < noisy.image.pixels.size(); ++i)
    if (noisy.coverage[i / 3]) noisy.image.pixels[i] = std::max(0.001f, noisy.image.pixels[i] + n(rng));
  const ImageComparison r = compareImages(ref, noisy);
  EXPECT_DOUBLE_EQ(r.iou, 1.0);
  EXPECT_LT(r.ssim, 0.9);
  EXPECT_GT(r.relative_rmse, 0.05);
}

TEST(ImageCompare, DisjointMasksHaveNoOverlap) {
  const CoveredImage a = disc(64, 16, 32, 10);
  const CoveredImage b = disc(64, 48, 32, 10);
  const ImageComparison r = compareImages(a, b);
  EXPECT_DOUBLE_EQ(r.iou, 0.0);
  EXPECT_EQ(r.joint_pixels, 0);
  EXPECT_DOUBLE_EQ(r.scale, 1.0);  // nothing to fit: the neutral scale
}

TEST(ImageCompare, HalfOverlapGivesExpectedIou) {
  // Two 10x20 rectangles sharing 10x10: IoU = 100 / 300.
  CoveredImage a, b;
  for (CoveredImage* c : {&a, &b}) {
    c->image = ImageRGBF{40, 40, std::vector<float>(40 * 40 * 3, 0.0f)};
    c->coverage.assign(40 * 40, 0);
  }
  for (int y = 10; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      a.coverage[static_cast<size_t>(y) * 40 + x] = 1;
      b.coverage[static_cast<size_t>(y) * 40 + x + 10] = 1;
    }
  EXPECT_NEAR(compareImages(a, b).iou, 1.0 / 3.0, 1e-12);
}

TEST(ImageCompare, SizeMismatchIsRefused) {
  EXPECT_THROW(compareImages(disc(32, 16, 16, 8), disc(33, 16, 16, 8)), std::invalid_argument);
}

TEST(ImageCompare, ToneMapMatchesPostShader) {
  // Below PBR Neutral's knee (0.76) only the small toe offset applies: 0.5 grey becomes 0.46,
  // sRGB-encoded 0.7114; black stays black; very bright saturates toward white.
  EXPECT_NEAR(toneMapForDisplay(glm::vec3(0.5f)).g, 1.055 * std::pow(0.46, 1 / 2.4) - 0.055, 1e-4);
  EXPECT_FLOAT_EQ(toneMapForDisplay(glm::vec3(0.0f)).r, 0.0f);
  EXPECT_GT(toneMapForDisplay(glm::vec3(100.0f, 10.0f, 1.0f)).b, 0.9f);
}
