// Antialiasing in the renderer (RenderSettings::antialias): FXAA after the post pass changes
// only pixels on contrast edges, follows the frame's size, is timed, and stays out of the floor
// mode. (That `none` gives the picture from before FXAA is checked by the golden
// tests/golden/marble-no-aa.png; FXAA itself on synthetic edges in fxaa_gl_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "gl_support.h"

using namespace marble;
using namespace marble::test;

namespace {

Scene sceneOf(RenderMode mode, Antialias aa, int width = 128, int height = 112) {
  Scene s;
  s.mesh = "builtin:sculpture";
  s.render.width = width;
  s.render.height = height;
  s.render.mode = mode;
  s.render.antialias = aa;
  return s;
}

struct AntialiasFixture : ::testing::Test {
  HeadlessContext& context = glContext();  // before the renderer: it needs a current context
  Renderer renderer;
  AntialiasFixture() { renderer.setMesh(builtinMesh("sculpture")); }
};

// Whether every pixel of the 3 x 3 neighbourhood (clamped at the border) has the centre's colour.
bool flatAround(const ImageRGBA8& img, int x, int y) {
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      if (img.at(std::clamp(x + i, 0, img.width - 1), std::clamp(y + j, 0, img.height - 1)) != img.at(x, y)) return false;
  return true;
}

}  // namespace

TEST_F(AntialiasFixture, FxaaChangesOnlyPixelsOnEdges) {
  for (RenderMode mode : {RenderMode::Marble, RenderMode::Paper, RenderMode::Normal}) {
    const ImageRGBA8 plain = renderImage(renderer, sceneOf(mode, Antialias::None));
    const ImageRGBA8 smooth = renderImage(renderer, sceneOf(mode, Antialias::Fxaa));
    ASSERT_EQ(smooth.width, plain.width);
    ASSERT_EQ(smooth.height, plain.height);
    int flat = 0, changed = 0;
    for (int y = 0; y < plain.height; ++y)
      for (int x = 0; x < plain.width; ++x) {
        changed += smooth.at(x, y) != plain.at(x, y);
        if (!flatAround(plain, x, y)) continue;
        ++flat;
        ASSERT_EQ(smooth.at(x, y), plain.at(x, y)) << renderModeName(mode) << ": flat pixel " << x << "," << y << " changed";
      }
    EXPECT_GT(flat, plain.width * plain.height / 2) << renderModeName(mode) << ": the background at least";
    EXPECT_GT(changed, 100) << renderModeName(mode) << ": the silhouette is smoothed";
    // Edges are a small part of the picture, and a blend moves a pixel only part of the way.
    EXPECT_LT(meanAbsDiff(plain, smooth), 2.0) << renderModeName(mode);
  }
}

TEST_F(AntialiasFixture, TheDisplayImageFollowsTheFrameSize) {
  renderImage(renderer, sceneOf(RenderMode::Marble, Antialias::Fxaa, 64, 48));
  const ImageRGBA8 resized = renderImage(renderer, sceneOf(RenderMode::Marble, Antialias::Fxaa, 96, 80));
  ASSERT_EQ(resized.width, 96);
  ASSERT_EQ(resized.height, 80);
  Renderer fresh;
  fresh.setMesh(builtinMesh("sculpture"));
  EXPECT_EQ(resized.pixels, renderImage(fresh, sceneOf(RenderMode::Marble, Antialias::Fxaa, 96, 80)).pixels);
}

TEST_F(AntialiasFixture, FxaaIsTimedAndNeedsNoMemoryOfItsOwn) {
  renderImage(renderer, sceneOf(RenderMode::Marble, Antialias::None));
  const size_t without = renderer.glBytes();
  renderImage(renderer, sceneOf(RenderMode::Marble, Antialias::Fxaa));
  EXPECT_GT(renderer.passTimes(true).ms[Pass::Fxaa], 0.0);
  // It reads the display image the post pass always writes (and copies when FXAA is off).
  EXPECT_EQ(renderer.glBytes(), without);
}

TEST_F(AntialiasFixture, TheFloorModeIsNotAntialiased) {
  const ImageRGBA8 plain = renderImage(renderer, sceneOf(RenderMode::Floor, Antialias::None));
  EXPECT_EQ(renderImage(renderer, sceneOf(RenderMode::Floor, Antialias::Fxaa)).pixels, plain.pixels);
}
