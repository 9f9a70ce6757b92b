// The exported .glb in a real web viewer: three.js (tools/web/compare.html) in headless Debian
// chromium (tools/web/shoot.mjs) against `marble render` of the same scene. In `albedo` mode both
// show the stone's colour unlit and linear (three.js reads the baked texture through the file's
// UVs; marble evaluates the pattern per pixel), so the silhouettes must agree (IoU >= 0.98) and
// the mean colour over the object within 3/255 per channel. Skipped when chromium or three.js is
// missing, unless MARBLE_REQUIRE_WEB_TOOLS is set (tools/test.sh, after tools/setup.sh).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cli_support.h"
#include "marble/core/image.h"

namespace {

namespace fs = std::filesystem;

struct Agreement {
  double iou = 0;
  glm::dvec3 meanA{0}, meanB{0};
};

// Object = any channel above 4/255 on a black background.
Agreement compare(const marble::ImageRGBA8& a, const marble::ImageRGBA8& b) {
  Agreement r;
  size_t both = 0, either = 0, na = 0, nb = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const glm::u8vec4 pa = a.at(x, y), pb = b.at(x, y);
      const bool ia = pa.r > 4 || pa.g > 4 || pa.b > 4, ib = pb.r > 4 || pb.g > 4 || pb.b > 4;
      both += ia && ib;
      either += ia || ib;
      if (ia) r.meanA += glm::dvec3(pa.r, pa.g, pa.b), ++na;
      if (ib) r.meanB += glm::dvec3(pb.r, pb.g, pb.b), ++nb;
    }
  r.iou = either ? static_cast<double>(both) / static_cast<double>(either) : 0;
  if (na) r.meanA /= static_cast<double>(na);
  if (nb) r.meanB /= static_cast<double>(nb);
  return r;
}

}  // namespace

TEST(WebViewer, ThreeJsShowsTheExportAsMarbleRendersIt) {
  const fs::path web = fs::path(MARBLE_SOURCE_DIR) / "tools" / "web";
  const bool haveTools = fs::exists(web / "node_modules" / "three") && std::system("command -v chromium > /dev/null 2>&1") == 0 &&
                         std::system("command -v node > /dev/null 2>&1") == 0;
  if (!haveTools) {
    const char* why = "chromium, node or three.js missing (tools/deps.txt, tools/setup-web-tools.sh)";
    if (std::getenv("MARBLE_REQUIRE_WEB_TOOLS")) FAIL() << why;
    GTEST_SKIP() << why;
  }
  const auto dir = marble::test::tempDir("web-viewer");
  std::ofstream(dir / "scene.json") << R"({"mesh": "builtin:sculpture", "material": {"preset": "calacatta"},
    "render": {"width": 256, "height": 256, "mode": "albedo", "antialias": "none", "background": [0, 0, 0]}})";
  const auto e = marble::test::runMarble("export " + (dir / "scene.json").string() + " --size 512 -o " + (dir / "m.glb").string());
  ASSERT_EQ(e.exitCode, 0) << e.output;
  const auto r = marble::test::runMarble("render " + (dir / "scene.json").string() + " -o " + (dir / "marble.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string shoot = "node " + (web / "shoot.mjs").string() + " " + (dir / "m.glb").string() + " " +
                            (dir / "three.png").string() + " --width 256 --height 256 --mode albedo 2>&1";
  ASSERT_EQ(std::system(shoot.c_str()), 0) << shoot;
  const Agreement a = compare(marble::readPng(dir / "marble.png"), marble::readPng(dir / "three.png"));
  EXPECT_GE(a.iou, 0.98);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.meanA[c], a.meanB[c], 3.0) << "channel " << c;
  std::printf("IoU %.4f, mean colour marble (%.1f %.1f %.1f) three.js (%.1f %.1f %.1f)\n", a.iou, a.meanA.x, a.meanA.y, a.meanA.z,
              a.meanB.x, a.meanB.y, a.meanB.z);
  // Negative control: a different stone must be told apart by the same measure.
  const auto e2 = marble::test::runMarble("export " + (dir / "scene.json").string() + " --preset nero-marquina --size 128 -o " +
                                          (dir / "black.glb").string());
  ASSERT_EQ(e2.exitCode, 0) << e2.output;
  const std::string shoot2 = "node " + (web / "shoot.mjs").string() + " " + (dir / "black.glb").string() + " " +
                             (dir / "black.png").string() + " --width 256 --height 256 --mode albedo 2>&1";
  ASSERT_EQ(std::system(shoot2.c_str()), 0);
  const Agreement other = compare(marble::readPng(dir / "marble.png"), marble::readPng(dir / "black.png"));
  double far = 0;
  for (int c = 0; c < 3; ++c) far = std::max(far, std::abs(other.meanA[c] - other.meanB[c]));
  EXPECT_GT(far, 10.0);
}
