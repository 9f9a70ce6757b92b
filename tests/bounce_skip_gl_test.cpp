// The `marble` bounce pass's draws skip the background by the depth test (BounceGridDepth,
// shaders/bounce_grid_depth.frag.glsl): a texel is shaded only where the pixel its draw reads is
// stone, and a skipped texel keeps the clear's alpha -1, which its draw would have written. The
// frame must therefore equal, bit for bit, the one whose bounce draws shade every texel of the
// object's rectangle (BouncePass::setSkipsBackground(false)), on both of the bounce's grids
// (8 pixels at the blur's half resolution, 4 at full) and after a base colour change, which runs the
// merge alone on the depth of the last gather.
// Negative controls (by hand, session 21): with bounce_grid_depth.frag.glsl reading the pixel one
// to the right of t * u_scale, texels on the silhouette whose own pixel is stone are skipped and
// the frames differ; with the further bounces' clear cut by the first draw's scissor (as before
// session 21), skipped texels outside that cut keep undefined values, which the merge reads, and
// the frames differ (742 and 652 values).
#include <gtest/gtest.h>

#include <algorithm>

#include "gl_support.h"
#include "principled_stone.h"

using namespace marble;
using namespace marble::test;

namespace {

Scene scene(SubsurfaceResolution resolution) {
  Scene s;
  s.render.width = s.render.height = 160;
  s.render.mode = RenderMode::Marble;
  s.render.subsurface_resolution = resolution;
  s.material = test::principledStone(glm::vec3(0.8f));
  return s;
}

size_t differingValues(const ImageRGBF& a, const ImageRGBF& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  size_t differ = 0;
  for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i) differ += a.pixels[i] != b.pixels[i];
  return differ;
}

void expectSkipChangesNothing(SubsurfaceResolution resolution) {
  glContext();
  Renderer skipped, full;
  full.setBounceSkipsBackground(false);
  skipped.setMesh(builtinMesh(kDefaultBuiltinMesh));
  full.setMesh(builtinMesh(kDefaultBuiltinMesh));
  Scene s = scene(resolution);
  // Each frame read back before the other renderer draws (readHdr runs the post pass again).
  const auto frame = [&s](Renderer& r) {
    renderImage(r, s);
    return r.readHdr();
  };
  EXPECT_EQ(differingValues(frame(skipped), frame(full)), 0u);
  // The merge alone (the gather's depth of the last frame).
  s.material.base_color = glm::vec3(0.3f, 0.6f, 0.2f);
  EXPECT_EQ(differingValues(frame(skipped), frame(full)), 0u) << "after a base colour change";
}

}  // namespace

TEST(BounceSkip, TheFrameEqualsTheUnskippedDrawsAtTheBlursHalfResolution) {
  expectSkipChangesNothing(SubsurfaceResolution::Half);
}

TEST(BounceSkip, TheFrameEqualsTheUnskippedDrawsAtFullResolution) {
  expectSkipChangesNothing(SubsurfaceResolution::Full);
}
