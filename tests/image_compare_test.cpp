// The comparison figures of `marble compare` on images whose answer is known.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <unistd.h>

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

// --- coverage alpha (issue 5: --hdr writes coverage; compare uses it when both files have it) ---

namespace {

// A 16x16 image: a covered 8x8 square in the middle whose left half is black (covered but
// unlit, like the dark side of a back-lit statue), the rest lit; background 0.
ImageRGBF squareWithDarkHalf(bool withAlpha) {
  ImageRGBF img{16, 16, std::vector<float>(16 * 16 * 3, 0.0f)};
  if (withAlpha) img.alpha.assign(16 * 16, 0.0f);
  for (int y = 4; y < 12; ++y)
    for (int x = 4; x < 12; ++x) {
      const size_t i = static_cast<size_t>(y) * 16 + x;
      if (withAlpha) img.alpha[i] = 1.0f;
      if (x >= 8)
        for (int c = 0; c < 3; ++c) img.pixels[i * 3 + c] = 0.25f * static_cast<float>(c + 1);
    }
  return img;
}

std::filesystem::path tempExr(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("marble-image-compare-" + std::to_string(::getpid()) + "-" + name);
}

}  // namespace

TEST(ExrAlpha, RoundTripKeepsRadianceAndCoverage) {
  const ImageRGBF img = squareWithDarkHalf(true);
  const auto path = tempExr("alpha.exr");
  writeExr(path, img);
  bool marked = false;
  const ImageRGBF back = readExr(path, &marked);
  std::filesystem::remove(path);
  EXPECT_TRUE(marked) << "marble's EXR says its alpha is coverage";
  ASSERT_EQ(back.width, 16);
  ASSERT_EQ(back.height, 16);
  EXPECT_EQ(back.pixels, img.pixels);  // 0, 0.25, 0.5, 0.75 are exact in half floats
  EXPECT_EQ(back.alpha, img.alpha);
}

TEST(ExrAlpha, FileWithoutCoverageReadsAsAlphaOneUnmarked) {
  // What --hdr wrote before coverage: A = 1 everywhere. It must not be mistaken for coverage.
  const auto path = tempExr("opaque.exr");
  writeExr(path, squareWithDarkHalf(false));
  bool marked = true;
  const ImageRGBF back = readExr(path, &marked);
  EXPECT_FALSE(marked);
  ASSERT_EQ(back.alpha.size(), 256u);
  for (float a : back.alpha) EXPECT_EQ(a, 1.0f);
  EXPECT_FALSE(coverageFromAlpha(back, marked).has_value());
  const CoveredImage c = readExrWithCoverage(path);
  std::filesystem::remove(path);
  EXPECT_EQ(c.source, CoverageSource::Values);
}

TEST(ExrAlpha, MarkedAlphaOfOneEverywhereIsCoverage) {
  // An object filling the whole frame: every alpha is 1, and the mark says that is coverage.
  ImageRGBF img{4, 4, std::vector<float>(4 * 4 * 3, 0.0f), std::vector<float>(16, 1.0f)};
  EXPECT_TRUE(coverageFromAlpha(img, true).has_value());
  EXPECT_FALSE(coverageFromAlpha(img, false).has_value());
  img.alpha[3] = 0.0f;  // some background: coverage even unmarked (Cycles' transparent film)
  EXPECT_TRUE(coverageFromAlpha(img, false).has_value());
}

TEST(ExrAlpha, CompareUsesAlphaSoCoveredBlackPixelsCount) {
  const auto refPath = tempExr("ref.exr"), testPath = tempExr("test.exr");
  writeExr(refPath, squareWithDarkHalf(true));
  writeExr(testPath, squareWithDarkHalf(true));
  const CoveredImage ref = readExrWithCoverage(refPath), test = readExrWithCoverage(testPath);
  EXPECT_EQ(ref.source, CoverageSource::Alpha);
  EXPECT_EQ(test.source, CoverageSource::Alpha);
  EXPECT_EQ(ref.coverage, test.coverage);
  const ImageComparison withAlpha = compareImages(ref, test);
  EXPECT_EQ(withAlpha.ref_pixels, 64);  // all of the square, its black half included
  EXPECT_DOUBLE_EQ(withAlpha.iou, 1.0);

  // The old rule on the test file alone (as for an --hdr written before coverage): its black half
  // is called background, and IoU against the reference's alpha drops to 32 / 64.
  writeExr(testPath, squareWithDarkHalf(false));
  const CoveredImage oldTest = readExrWithCoverage(testPath);
  EXPECT_EQ(oldTest.source, CoverageSource::Values);
  const ImageComparison mixed = compareImages(ref, oldTest);
  EXPECT_EQ(mixed.test_pixels, 32);
  EXPECT_DOUBLE_EQ(mixed.iou, 0.5);
  std::filesystem::remove(refPath);
  std::filesystem::remove(testPath);
}
