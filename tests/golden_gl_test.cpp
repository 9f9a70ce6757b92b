// Golden images: marble, phong and oren-nayar on the built-in mesh (antialiased with FXAA, the
// default), and marble without antialiasing (`marble-no-aa.png`: the picture from before FXAA
// existed, so `antialias: none` is checked to give the old output), compared with PNGs in
// tests/golden/. Tolerance (stated, and the same for every image): at most 0.5% of the
// pixels may differ by more than 3/255 in any channel, and none by more than 64/255 — room
// for rasterization differences at silhouettes between Mesa versions or GPUs, none for a
// change in shading. Regenerate on purpose with tools/update-goldens.sh (it sets
// MARBLE_UPDATE_GOLDENS=1 and runs this test, which then writes the PNGs).
#include <gtest/gtest.h>

#include <cstdlib>
#include <ostream>
#include <string>

#include "gl_support.h"
#include "marble/core/image.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 160;
constexpr int kSmallDiff = 3, kMaxDiff = 64;
constexpr double kAllowedFraction = 0.005;

struct GoldenCase {
  RenderMode mode;
  Antialias antialias;
  std::string name() const { return renderModeName(mode) + (antialias == Antialias::None ? "-no-aa" : ""); }
};

void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name(); }

class Golden : public ::testing::TestWithParam<GoldenCase> {};

}  // namespace

TEST_P(Golden, MatchesReferenceImage) {
  glContext();
  Renderer renderer;
  renderer.setMesh(builtinMesh(kDefaultBuiltinMesh));
  Scene s;
  s.render.width = s.render.height = kSize;
  s.render.mode = GetParam().mode;
  s.render.antialias = GetParam().antialias;
  const ImageRGBA8 img = renderImage(renderer, s);
  const std::string path = std::string(MARBLE_GOLDEN_DIR) + "/" + GetParam().name() + ".png";
  if (const char* update = std::getenv("MARBLE_UPDATE_GOLDENS"); update && std::string(update) == "1") {
    writePng(path, img);
    GTEST_SKIP() << "wrote " << path;
  }
  const ImageRGBA8 ref = readPng(path);
  ASSERT_EQ(ref.width, img.width);
  ASSERT_EQ(ref.height, img.height);
  int over = 0, worst = 0;
  for (size_t i = 0; i < img.pixels.size(); i += 4) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(img.pixels[i + c]) - int(ref.pixels[i + c])));
    worst = std::max(worst, d);
    if (d > kSmallDiff) ++over;
  }
  EXPECT_LE(over, static_cast<int>(kAllowedFraction * kSize * kSize)) << path << ": pixels over tolerance";
  EXPECT_LE(worst, kMaxDiff) << path;
}

INSTANTIATE_TEST_SUITE_P(BuiltinMesh, Golden,
                         ::testing::Values(GoldenCase{RenderMode::Marble, Antialias::Fxaa},
                                           GoldenCase{RenderMode::Phong, Antialias::Fxaa},
                                           GoldenCase{RenderMode::OrenNayar, Antialias::Fxaa},
                                           GoldenCase{RenderMode::Marble, Antialias::None}),
                         [](const auto& info) {
                           std::string n = info.param.name();
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });
