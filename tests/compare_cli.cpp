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

  const auto j = runMarble("compare --json " + (dir / "ref.exr").string() + " " + (dir / "ref.exr").string());
  EXPECT_EQ(j.exitCode, 0) << j.output;
  EXPECT_EQ(lineCount(j.output), 1) << j.output;
  EXPECT_NE(j.output.find("\"iou\": 1.000000"), std::string::npos) << j.output;
  EXPECT_NE(j.output.find("\"scale\": 1.000000"), std::string::npos) << j.output;
  EXPECT_NE(j.output.find("\"relative_rmse\": 0.000000"), std::string::npos) << j.output;
  EXPECT_NE(j.output.find("\"ssim\": 1.000000"), std::string::npos) << j.output;
  std::filesystem::remove_all(dir);
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
  std::filesystem::remove_all(dir);
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
  std::filesystem::remove_all(dir);
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
  std::filesystem::remove_all(dir);
}
