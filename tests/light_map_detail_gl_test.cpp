// Interaction detail for the light's maps (Renderer::setLightMapDetail, the viewer's
// `--interaction-light-maps`): while the object or the light moves, the light's maps are drawn
// at the resolution scale's share of their size.
// - a frame drawn with the reduced maps is what a fresh renderer with the same settings draws
//   (nothing of the full-size maps is read), and another picture than one from the full maps;
// - with a light proxy (a mesh above kLightProxyMinTriangles), the reduced maps draw a coarser
//   copy of the proxy, and the still frame is still a fresh renderer's;
// - the first still frame after such frames -- the object turning, the light turning on a stage
//   -- equals a fresh full render bit for bit, though its model and light are the last moving
//   frame's (the light's pass must re-run for the size alone).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "dense_mesh.h"
#include "gl_support.h"
#include "turning_scene.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 192;

const Mesh& sculpture() {
  static const Mesh m = builtinMesh("sculpture");  // 25,600 triangles: no proxy
  return m;
}
const Mesh& denseSculpture() {
  static const Mesh m = subdividedSmoothed(builtinMesh("sculpture"), 1);  // 102,400: a proxy
  return m;
}

Scene marbleScene() { return marbleSceneOfSize(kSize); }

ImageRGBA8 render(Renderer& r, const Scene& s, const glm::mat4& model) {
  OffscreenTarget target(kSize, kSize);
  r.render(s, model, target.fbo(), kSize, kSize);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return target.read();
}

// Frames while the object (or the light) turns at half resolution with the light's maps at
// interaction detail, arriving at `model` and s's light; then the first still frame.
ImageRGBA8 movingThenStill(const Scene& s, const glm::mat4& model, bool turnLight, const Mesh& mesh = sculpture()) {
  Renderer r;
  r.setMesh(mesh);
  OffscreenTarget target(kSize, kSize);
  for (int i = 3; i >= 0; --i) {
    r.setResolutionScale(0.5f);
    r.setLightMapDetail(Renderer::LightMapDetail::Interaction);
    Scene moving = s;
    glm::mat4 movingModel = model;
    if (turnLight)
      moving.light.position = turnedAboutY(s.light.position, 5.0f * float(i));
    else
      movingModel = model * turnedModel(4.0f * float(i));
    r.render(moving, movingModel, target.fbo(), kSize, kSize);
    EXPECT_EQ(r.lightMapSize(), 512);
  }
  r.setResolutionScale(1.0f);  // the first still frame, as the viewer sets it
  r.setLightMapDetail(Renderer::LightMapDetail::Full);
  EXPECT_EQ(r.lightMapSize(), 1024);
  return render(r, s, model);
}

ImageRGBA8 fresh(const Scene& s, const glm::mat4& model, float scale, Renderer::LightMapDetail maps,
                 const Mesh& mesh = sculpture()) {
  Renderer r;
  r.setMesh(mesh);
  r.setResolutionScale(scale);
  r.setLightMapDetail(maps);
  return render(r, s, model);
}

}  // namespace

TEST(LightMapDetail, FollowsTheResolutionScaleOnlyWhenAskedFor) {
  glContext();
  Renderer r;
  EXPECT_EQ(r.lightMapSize(), 1024);
  r.setResolutionScale(0.5f);
  EXPECT_EQ(r.lightMapSize(), 1024) << "Full: the camera moving alone keeps the maps";
  r.setLightMapDetail(Renderer::LightMapDetail::Interaction);
  EXPECT_EQ(r.lightMapSize(), 512);
  r.setResolutionScale(0.3f);
  EXPECT_EQ(r.lightMapSize(), 307);
  r.setResolutionScale(1.0f);
  EXPECT_EQ(r.lightMapSize(), 1024);
}

TEST(LightMapDetail, ReducedMapsFrameIsAFreshRenderersAndAnotherPicture) {
  glContext();
  const Scene s = marbleScene();
  const glm::mat4 model = turnedModel(20.0f);
  // A renderer that drew full-size maps first, then reduced ones for a turned object.
  Renderer r;
  r.setMesh(builtinMesh("sculpture"));
  r.setResolutionScale(0.5f);
  render(r, s, glm::mat4(1.0f));
  r.setLightMapDetail(Renderer::LightMapDetail::Interaction);
  const ImageRGBA8 got = render(r, s, model);
  const ImageRGBA8 expected = fresh(s, model, 0.5f, Renderer::LightMapDetail::Interaction);
  EXPECT_TRUE(got.pixels == expected.pixels) << "mean difference " << meanAbsDiff(got, expected);
  const ImageRGBA8 fullMaps = fresh(s, model, 0.5f, Renderer::LightMapDetail::Full);
  EXPECT_FALSE(got.pixels == fullMaps.pixels) << "the reduced maps are drawn and read";
}

TEST(LightMapDetail, StillFrameAfterTheObjectTurnedEqualsAFreshRender) {
  glContext();
  for (const Antialias aa : {Antialias::Fxaa, Antialias::None}) {
    SCOPED_TRACE(antialiasName(aa));
    Scene s = marbleScene();
    s.render.antialias = aa;
    const glm::mat4 model = turnedModel(30.0f);
    const ImageRGBA8 still = movingThenStill(s, model, false);
    const ImageRGBA8 reference = fresh(s, model, 1.0f, Renderer::LightMapDetail::Full);
    EXPECT_TRUE(still.pixels == reference.pixels) << "mean difference " << meanAbsDiff(still, reference);
  }
}

TEST(LightMapDetail, StillFrameAfterTheLightTurnedOnAStageEqualsAFreshRender) {
  glContext();
  Scene s = marbleScene();
  s.render.ground = true;
  s.render.backdrop = true;
  const ImageRGBA8 still = movingThenStill(s, glm::mat4(1.0f), true);
  const ImageRGBA8 reference = fresh(s, glm::mat4(1.0f), 1.0f, Renderer::LightMapDetail::Full);
  EXPECT_TRUE(still.pixels == reference.pixels) << "mean difference " << meanAbsDiff(still, reference);
}

TEST(LightMapDetail, WithAProxyTheReducedMapsDrawACoarserCopyAndTheStillFrameIsFresh) {
  glContext();
  const Scene s = marbleScene();
  Renderer r;
  r.setMesh(denseSculpture());
  ASSERT_LT(r.lightTriangleCount(), r.triangleCount()) << "the mesh has a light proxy";
  EXPECT_EQ(r.lightMapTriangleCount(), r.lightTriangleCount()) << "full-size maps: the proxy";
  r.setResolutionScale(0.5f);
  r.setLightMapDetail(Renderer::LightMapDetail::Interaction);
  EXPECT_LT(r.lightMapTriangleCount(), r.lightTriangleCount()) << "512² maps: a coarser copy";
  EXPECT_GT(r.lightMapTriangleCount(), 0u);
  // A frame from the coarser copy is a fresh renderer's with the same settings.
  const glm::mat4 model = turnedModel(20.0f);
  const ImageRGBA8 got = render(r, s, model);
  const ImageRGBA8 expected = fresh(s, model, 0.5f, Renderer::LightMapDetail::Interaction, denseSculpture());
  EXPECT_TRUE(got.pixels == expected.pixels) << "mean difference " << meanAbsDiff(got, expected);
  // The still frame after the object turned: the full proxy into full-size maps again.
  const ImageRGBA8 still = movingThenStill(s, model, false, denseSculpture());
  const ImageRGBA8 reference = fresh(s, model, 1.0f, Renderer::LightMapDetail::Full, denseSculpture());
  EXPECT_TRUE(still.pixels == reference.pixels) << "mean difference " << meanAbsDiff(still, reference);
}
