// Dynamic resolution (Renderer::setResolutionScale, the viewer's `--interaction-resolution`):
// - a reduced frame is exactly a fresh renderer's frame at the reduced size, stretched
//   bilinearly to the target (so it is what the setting says, and nothing is reused from the
//   full-size passes);
// - the first frame at scale 1 after reduced ones -- camera orbiting, light turning, with FXAA
//   and with a stage -- equals a fresh full render bit for bit;
// - a frame is current only at the scale it was drawn at.
#include <gtest/gtest.h>

#include <cmath>

#include "gl_support.h"
#include "turning_scene.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 192;

Scene marbleScene() { return marbleSceneOfSize(kSize); }

ImageRGBA8 freshFull(const Scene& s) {
  Renderer fresh;
  fresh.setMesh(builtinMesh("sculpture"));
  return renderImage(fresh, s);
}

// Frames while the camera (and, with `turnLight`, the light) moves at half resolution, then the
// first still frame at full resolution; returns the still frame and the last moving one.
std::pair<ImageRGBA8, ImageRGBA8> movingThenStill(const Scene& s, bool turnLight) {
  glContext();
  Renderer r;
  r.setMesh(builtinMesh("sculpture"));
  OffscreenTarget target(kSize, kSize);
  r.setResolutionScale(0.5f);
  Scene moving = s;
  for (int i = 3; i >= 0; --i) {  // arrives at the still frame's camera and light
    moving.camera.position = turnedAboutY(s.camera.position, 3.0f * float(i));
    if (turnLight) moving.light.position = turnedAboutY(s.light.position, 5.0f * float(i));
    r.render(moving, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  }
  const ImageRGBA8 lastMoving = target.read();
  const Renderer::FrameToken shown = r.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  EXPECT_TRUE(r.isCurrent(s, glm::mat4(1.0f), shown, kSize, kSize)) << "same scene, same scale: nothing to draw";
  r.setResolutionScale(1.0f);  // the first still frame
  EXPECT_FALSE(r.isCurrent(s, glm::mat4(1.0f), shown, kSize, kSize)) << "a reduced frame is not the full one";
  r.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return {target.read(), lastMoving};
}

}  // namespace

// The renderer stretches only where the reduced frame has content and clears the rest to the
// background (Renderer::stretchReducedFrame): the same picture as stretching the whole frame.
TEST(ResolutionScale, ReducedFrameIsAFreshSmallFrameStretched) {
  glContext();
  for (const float scale : {0.5f, 0.3f})
    for (const Antialias aa : {Antialias::Fxaa, Antialias::None})
      for (const bool stage : {false, true}) {
        SCOPED_TRACE(testing::Message() << "scale " << scale << ", " << antialiasName(aa) << (stage ? ", stage" : ""));
        Scene s = marbleScene();
        s.render.antialias = aa;
        s.render.ground = stage;
        Renderer reduced;
        reduced.setMesh(builtinMesh("sculpture"));
        reduced.setResolutionScale(scale);
        const ImageRGBA8 got = renderImage(reduced, s);

        const int small = static_cast<int>(std::lround(kSize * scale));
        Scene smallScene = s;
        smallScene.render.width = smallScene.render.height = small;
        Renderer fresh;
        fresh.setMesh(builtinMesh("sculpture"));
        OffscreenTarget smallTarget(small, small), target(kSize, kSize);
        fresh.render(smallScene, glm::mat4(1.0f), smallTarget.fbo(), small, small);
        glBlitNamedFramebuffer(smallTarget.fbo(), target.fbo(), 0, 0, small, small, 0, 0, kSize, kSize,
                               GL_COLOR_BUFFER_BIT, GL_LINEAR);
        const ImageRGBA8 expected = target.read();
        EXPECT_TRUE(got.pixels == expected.pixels) << "mean difference " << meanAbsDiff(got, expected);
        // Negative control: the full frame is another picture.
        const ImageRGBA8 full = freshFull(s);
        EXPECT_FALSE(got.pixels == full.pixels);
        EXPECT_GT(meanAbsDiff(got, full), 0.05);
      }
}

TEST(ResolutionScale, StillFrameAfterTheCameraMovedEqualsAFreshRender) {
  const Scene s = marbleScene();
  const auto [still, lastMoving] = movingThenStill(s, false);
  const ImageRGBA8 reference = freshFull(s);
  EXPECT_TRUE(still.pixels == reference.pixels) << "mean difference " << meanAbsDiff(still, reference);
  EXPECT_FALSE(lastMoving.pixels == reference.pixels) << "the moving frames were drawn at half resolution";
}

TEST(ResolutionScale, StillFrameAfterTheLightTurnedOnAStageEqualsAFreshRender) {
  Scene s = marbleScene();
  s.render.ground = true;
  s.render.backdrop = true;
  const auto [still, lastMoving] = movingThenStill(s, true);
  const ImageRGBA8 reference = freshFull(s);
  EXPECT_TRUE(still.pixels == reference.pixels) << "mean difference " << meanAbsDiff(still, reference);
  EXPECT_FALSE(lastMoving.pixels == reference.pixels);
}

TEST(ResolutionScale, StillFrameWithoutAntialiasingEqualsAFreshRender) {
  Scene s = marbleScene();
  s.render.antialias = Antialias::None;
  const auto [still, lastMoving] = movingThenStill(s, false);
  EXPECT_TRUE(still.pixels == freshFull(s).pixels);
}

TEST(ResolutionScale, IsClampedAndOneIsOff) {
  glContext();
  Renderer r;
  r.setResolutionScale(0.01f);
  EXPECT_EQ(r.resolutionScale(), Renderer::kMinResolutionScale);
  r.setResolutionScale(3.0f);
  EXPECT_EQ(r.resolutionScale(), 1.0f);
}
