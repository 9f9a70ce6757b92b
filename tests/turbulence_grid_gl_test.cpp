// The renderer reads the pattern's turbulence from its baked grid where that is exact
// (render/turbulence_texture.h): the pictures equal those with the turbulence evaluated per
// pixel within rounding, in `marble` (post pass) and in the modes with an albedo pass; the grid
// is baked once per turbulence, not per frame or per colour change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "gl_support.h"

using namespace marble;
using namespace marble::test;

namespace {

int largestChannelDifference(const ImageRGBA8& a, const ImageRGBA8& b) {
  int worst = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  return worst;
}

ImageRGBA8 renderWithGrid(const Scene& s, bool grid, size_t* gridBytes = nullptr) {
  Renderer renderer;
  renderer.setTurbulenceGridEnabled(grid);
  renderer.setMesh(builtinMesh("sculpture"));
  ImageRGBA8 image = renderImage(renderer, s);
  if (gridBytes) *gridBytes = renderer.glBytes();
  return image;
}

}  // namespace

TEST(TurbulenceGridRender, PicturesMatchPerPixelEvaluation) {
  glContext();
  for (RenderMode mode : {RenderMode::Marble, RenderMode::Albedo, RenderMode::Paper}) {
    for (PatternMapping mapping : {PatternMapping::Solid, PatternMapping::Triplanar}) {
      Scene s;
      s.mesh = "builtin:sculpture";
      s.render.width = s.render.height = 96;
      s.render.mode = mode;
      s.material.mapping = mapping;
      // FXAA's edge test is a threshold: a one-level difference can flip it and move a pixel by
      // many levels. The pattern itself is compared here.
      s.render.antialias = Antialias::None;
      size_t withGrid = 0, without = 0;
      const ImageRGBA8 a = renderWithGrid(s, true, &withGrid);
      const ImageRGBA8 b = renderWithGrid(s, false, &without);
      EXPECT_GT(withGrid, without) << "the grid was used";
      // The pattern differs by < 2e-4 (pattern_gl_test): at most one 8-bit level, where a
      // value lies on a rounding boundary.
      EXPECT_LE(largestChannelDifference(a, b), 1) << renderModeName(mode) << " mapping " << static_cast<int>(mapping);
      EXPECT_LT(meanAbsDiff(a, b), 0.01);
    }
  }
}

TEST(TurbulenceGridRender, GridIsKeptWhileOnlyWhatFollowsTheTurbulenceChanges) {
  glContext();
  TurbulenceTexture grid;
  Material m;
  const GLuint first = grid.update(m);
  ASSERT_NE(first, 0u);
  m.turb_power = 8.0f;
  m.vein_color = {0.1f, 0.2f, 0.3f};
  EXPECT_EQ(grid.update(m), first) << "not baked again";
  m.basis = NoiseBasis::Perlin;
  EXPECT_EQ(grid.update(m), 0u) << "Perlin's basis is evaluated per pixel";
  grid.setEnabled(false);
  m.basis = NoiseBasis::Value;
  EXPECT_EQ(grid.update(m), 0u);
}
