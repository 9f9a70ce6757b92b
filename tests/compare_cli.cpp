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
