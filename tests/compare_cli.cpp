// `marble compare` end to end: the figures, the JSON form, and one line with exit code 2 for
// files it cannot use.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_support.h"
#include "marble/core/image.h"

using namespace marble;
using marble::test::runMarble;
using marble::test::tempDir;

namespace {

ImageRGBF square(int size, float value) {
  ImageRGBF img{size, size, std::vector<float>(static_cast<size_t>(size) * size * 3, 0.0f)};
  for (int y = size / 4; y < 3 * size / 4; ++y)
    for (int x = size / 4; x < 3 * size / 4; ++x)
      for (int c = 0; c < 3; ++c) img.pixels[(static_cast<size_t>(y) * size + x) * 3 + c] = value * (1 + x % 3);
  return img;
}

int lineCount(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace

TEST(CompareCli, ScaledCopyGivesItsScale) {
  const auto dir = tempDir("compare");
  writeExr(dir / "ref.exr", square(32, 0.25f));
  writeExr(dir / "test.exr", square(32, 0.125f));
  const auto r = runMarble("compare " + (dir / "ref.exr").string() + " " + (dir / "test.exr").string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("silhouette IoU   1.0000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("exposure scale   2.0000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("relative RMSE    0.0000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("SSIM             1.0000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("energy ratio     0.5000"), std::string::npos) << r.output;

  const auto j = runMarble("compare --json " + (dir / "ref.exr").string() + " " + (dir / "ref.exr").string());
  EXPECT_EQ(j.exitCode, 0) << j.output;
  EXPECT_EQ(lineCount(j.output), 1) << j.output;
  EXPECT_NE(j.output.find("\"iou\": 1.000000"), std::string::npos) << j.output;
  EXPECT_NE(j.output.find("\"scale\": 1.000000"), std::string::npos) << j.output;
  EXPECT_NE(j.output.find("\"relative_rmse\": 0.000000"), std::string::npos) << j.output;
  EXPECT_NE(j.output.find("\"ssim\": 1.000000"), std::string::npos) << j.output;
}

TEST(CompareCli, SaysWhichSilhouetteRuleItUsed) {
  const auto dir = tempDir("compare-alpha");
  ImageRGBF covered = square(32, 0.25f);
  covered.alpha.assign(32 * 32, 0.0f);
  for (int y = 8; y < 24; ++y)
    for (int x = 8; x < 24; ++x) covered.alpha[static_cast<size_t>(y) * 32 + x] = 1.0f;
  writeExr(dir / "alpha.exr", covered);
  writeExr(dir / "plain.exr", square(32, 0.25f));  // alpha 1 everywhere, unmarked: no coverage
  const auto both = runMarble("compare " + (dir / "alpha.exr").string() + " " + (dir / "alpha.exr").string());
  EXPECT_EQ(both.exitCode, 0) << both.output;
  EXPECT_NE(both.output.find("silhouettes      from alpha in both files"), std::string::npos) << both.output;
  const auto mixed = runMarble("compare --json " + (dir / "alpha.exr").string() + " " + (dir / "plain.exr").string());
  EXPECT_EQ(mixed.exitCode, 0) << mixed.output;
  EXPECT_NE(mixed.output.find("\"ref_coverage\": \"alpha\", \"test_coverage\": \"values\""), std::string::npos)
      << mixed.output;
}

TEST(CompareCli, RenderHdrCarriesCoverage) {
  // marble's own --hdr, compared with itself: both silhouettes come from alpha, and with the light
  // off (every pixel exactly 0) the object still covers the picture.
  const auto dir = tempDir("compare-render");
  const auto scene = dir / "dark.json";
  std::ofstream(scene) << R"({"mesh": "builtin:sphere", "light": {"intensity": 0},
                             "render": {"width": 48, "height": 48, "environment": "none"}})";
  const auto hdr = dir / "dark.exr";
  const auto r = runMarble("render " + scene.string() + " -o " + (dir / "dark.png").string() + " --hdr " + hdr.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto c = runMarble("compare --json " + hdr.string() + " " + hdr.string());
  EXPECT_EQ(c.exitCode, 0) << c.output;
  EXPECT_NE(c.output.find("\"ref_coverage\": \"alpha\", \"test_coverage\": \"alpha\""), std::string::npos) << c.output;
  EXPECT_EQ(c.output.find("\"ref_pixels\": 0,"), std::string::npos) << "the unlit sphere must count as covered: " << c.output;
}

TEST(CompareCli, BadFilesAreOneLineAndExitTwo) {
  const auto dir = tempDir("compare-bad");
  writeExr(dir / "ref.exr", square(32, 0.25f));
  writeExr(dir / "small.exr", square(16, 0.25f));
  std::ofstream(dir / "junk.exr") << "not an exr";

  const auto missing = runMarble("compare " + (dir / "ref.exr").string() + " " + (dir / "none.exr").string());
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_EQ(lineCount(missing.output), 1) << missing.output;
  EXPECT_NE(missing.output.find("none.exr"), std::string::npos) << missing.output;

  const auto junk = runMarble("compare " + (dir / "junk.exr").string() + " " + (dir / "ref.exr").string());
  EXPECT_EQ(junk.exitCode, 2);
  EXPECT_EQ(lineCount(junk.output), 1) << junk.output;
  EXPECT_NE(junk.output.find("junk.exr"), std::string::npos) << junk.output;

  const auto size = runMarble("compare " + (dir / "ref.exr").string() + " " + (dir / "small.exr").string());
  EXPECT_EQ(size.exitCode, 2);
  EXPECT_EQ(lineCount(size.output), 1) << size.output;
  EXPECT_NE(size.output.find("32x32 and 16x16"), std::string::npos) << size.output;

  const auto usage = runMarble("compare " + (dir / "ref.exr").string());
  EXPECT_EQ(usage.exitCode, 2);
}

// --downsample N box-filters both images first: per-pixel noise that averages to the reference
// within each block disappears (the point of comparing a path tracer's render at a downsample).
TEST(CompareCli, DownsampleAveragesPixelNoiseAway) {
  const auto dir = tempDir("compare-downsample");
  ImageRGBF flat{32, 32, std::vector<float>(32 * 32 * 3, 0.0f)}, noisy = flat;
  for (int y = 8; y < 24; ++y)
    for (int x = 8; x < 24; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t i = (static_cast<size_t>(y) * 32 + x) * 3 + c;
        flat.pixels[i] = 0.25f;
        noisy.pixels[i] = 0.25f + (((x + y) % 2) ? 0.1f : -0.1f);  // a checkerboard: 0 in every 2x2 block
      }
  writeExr(dir / "ref.exr", flat);
  writeExr(dir / "noisy.exr", noisy);
  const std::string files = (dir / "ref.exr").string() + " " + (dir / "noisy.exr").string();
  const auto full = runMarble("compare --json " + files);
  ASSERT_EQ(full.exitCode, 0) << full.output;
  EXPECT_EQ(full.output.find("\"relative_rmse\": 0.000000"), std::string::npos) << full.output;
  const auto half = runMarble("compare --downsample 2 " + files);
  ASSERT_EQ(half.exitCode, 0) << half.output;
  EXPECT_NE(half.output.find("relative RMSE    0.0000"), std::string::npos) << half.output;
  EXPECT_NE(half.output.find("SSIM             1.0000"), std::string::npos) << half.output;
  EXPECT_NE(half.output.find("compared at      downsample 2 (16x16)"), std::string::npos) << half.output;
  EXPECT_NE(half.output.find("(reference 64 px, test 64 px, both 64 px)"), std::string::npos) << half.output;

  const auto bad = runMarble("compare --downsample 3 " + files);
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_EQ(lineCount(bad.output), 1) << bad.output;
  EXPECT_NE(bad.output.find("ref.exr"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("--downsample"), std::string::npos) << bad.output;
}

// --side-by-side writes reference | test, the test at the best-fit exposure: for a scaled copy
// the two halves are the same picture; the background is black.
TEST(CompareCli, SideBySideShowsTheTestAtItsExposureScale) {
  const auto dir = tempDir("compare-sbs");
  writeExr(dir / "ref.exr", square(32, 0.25f));
  writeExr(dir / "test.exr", square(32, 0.125f));
  const auto png = dir / "sbs.png";
  const auto r = runMarble("compare " + (dir / "ref.exr").string() + " " + (dir / "test.exr").string() +
                           " --side-by-side " + png.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const ImageRGBA8 img = readPng(png);
  ASSERT_EQ(img.width, 64);
  ASSERT_EQ(img.height, 32);
  int differing = 0, lit = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) {
        const uint8_t left = img.pixels[(static_cast<size_t>(y) * 64 + x) * 4 + c];
        const uint8_t right = img.pixels[(static_cast<size_t>(y) * 64 + 32 + x) * 4 + c];
        differing += left != right;
        lit += left > 0;
      }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(lit, 0);
  EXPECT_EQ(img.pixels[0], 0) << "background black";
}
