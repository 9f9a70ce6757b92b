// Simplified copies of the mesh (render/mesh_detail.h), on a dense built-in mesh
// (tests/dense_mesh.h: the sculpture split to 102,400 triangles, above the light proxy's and the
// interaction copy's thresholds):
// - the light's pass from a proxy: the thickness it gives (mm) and the shadow edges of the
//   full `marble` picture stay within stated bounds of the full mesh's, with a negative control
//   (the light turned by 1°) showing the measure sees a shadow move;
// - interaction detail: the first still frame after frames drawn from the interaction copy is
//   exactly what a fresh renderer draws, and the moving frames really drew the copy.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "dense_mesh.h"
#include "gl_support.h"
#include "marble/render/mesh_detail.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 256;

const Mesh& denseSculpture() {
  static const Mesh m = subdividedSmoothed(builtinMesh("sculpture"), 1);
  return m;
}

Scene sceneOf(RenderMode mode) {
  Scene s;
  s.render.width = s.render.height = kSize;
  s.render.mode = mode;
  return s;
}

// The thickness view's HDR value is the thickness over kThicknessViewRange (lighting.frag.glsl).
std::vector<float> thicknessMm(Renderer& renderer, const Scene& scene, std::vector<bool>& covered) {
  OffscreenTarget target(kSize, kSize);
  renderer.render(scene, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  const ImageRGBF hdr = renderer.readHdr();
  std::vector<float> mm(static_cast<size_t>(kSize) * kSize);
  covered.assign(mm.size(), false);
  EXPECT_EQ(hdr.alpha.size(), mm.size());
  for (size_t i = 0; i < mm.size() && i < hdr.alpha.size(); ++i) {
    mm[i] = hdr.pixels[i * 3] * kThicknessViewRange * scene.mm_per_unit;
    covered[i] = hdr.alpha[i] == 1.0f;  // wholly on the object
  }
  return mm;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

// The object's pixels: where the depth view is the same on a black and on a white background.
std::vector<bool> objectMask(Renderer& renderer, Scene s) {
  s.render.mode = RenderMode::Depth;
  s.render.background = glm::vec3(0.0f);
  const ImageRGBA8 black = renderImage(renderer, s);
  s.render.background = glm::vec3(1.0f);
  const ImageRGBA8 white = renderImage(renderer, s);
  std::vector<bool> mask(black.pixels.size() / 4);
  for (size_t i = 0; i < mask.size(); ++i)
    mask[i] = std::equal(&black.pixels[i * 4], &black.pixels[i * 4 + 3], &white.pixels[i * 4]);
  return mask;
}

// Fraction of the object's pixels whose colour differs by more than 8/255 in any channel: a
// shadow edge that moved (shading noise of the same edge stays below that).
double changedFraction(const ImageRGBA8& a, const ImageRGBA8& b, const std::vector<bool>& object_) {
  int object = 0, changed = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    if (!object_[i / 4]) continue;
    ++object;
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])));
    if (d > 8) ++changed;
  }
  return object > 0 ? double(changed) / object : 1.0;
}

}  // namespace

TEST(LightProxy, DrawnAboveTheThresholdOnly) {
  glContext();
  Renderer dense;
  dense.setMesh(denseSculpture());
  ASSERT_GT(dense.triangleCount(), kLightProxyMinTriangles);
  EXPECT_LT(dense.lightTriangleCount(), dense.triangleCount() / 2);
  EXPECT_GT(dense.lightTriangleCount(), 0u);
  EXPECT_LE(dense.lightProxyErrorUnits(), lightProxyMaxErrorUnits(1024));
  Renderer small;
  small.setMesh(builtinMesh("sculpture"));  // 25,600 triangles: the light draws them all
  EXPECT_EQ(small.lightTriangleCount(), small.triangleCount());
  EXPECT_EQ(small.lightProxyErrorUnits(), 0.0f);
  dense.setLightProxyEnabled(false);
  EXPECT_EQ(dense.lightTriangleCount(), dense.triangleCount());
}

// Thickness through the proxy against the full mesh, per pixel of the object, in mm
// (mm_per_unit 100: the sculpture is 200 mm across; one texel of the light's map ≈ 0.34 mm).
TEST(LightProxy, ThicknessErrorIsBounded) {
  glContext();
  Renderer proxy, full;
  proxy.setMesh(denseSculpture());
  full.setMesh(denseSculpture());
  full.setLightProxyEnabled(false);
  const Scene s = sceneOf(RenderMode::Thickness);
  std::vector<bool> coveredP, coveredF;
  const std::vector<float> a = thicknessMm(proxy, s, coveredP);
  const std::vector<float> b = thicknessMm(full, s, coveredF);
  std::vector<double> err;
  double meanThickness = 0;
  for (size_t i = 0; i < a.size(); ++i)
    if (coveredP[i] && coveredF[i]) {
      err.push_back(std::abs(double(a[i]) - double(b[i])));
      meanThickness += b[i];
    }
  ASSERT_GT(err.size(), 5000u);
  meanThickness /= double(err.size());
  double mean = 0;
  for (double e : err) mean += e;
  mean /= double(err.size());
  const double p99 = quantile(err, 0.99);
  RecordProperty("thickness_mean_error_mm", std::to_string(mean));
  RecordProperty("thickness_p99_error_mm", std::to_string(p99));
  RecordProperty("thickness_mean_mm", std::to_string(meanThickness));
  // Bounds (measured: mean 0.034 mm of a mean thickness of 6.4 mm, p99 0.40 mm): the mean
  // within a seventh of a light texel; 99 % of pixels within two texels (0.68 mm) -- the proxy
  // moves the surface by at most half a texel along its normal, which the light sees
  // stretched by 1/cos of its angle to the surface; the last 1 % lie at the light's silhouette,
  // where a texel turns from surface to "nothing hit".
  EXPECT_LT(mean, 0.05) << "mean thickness " << meanThickness << " mm";
  EXPECT_LT(p99, 2.0 * 0.34);
}

// The `marble` picture: pixels whose colour changes visibly (a shadow edge or the thickness'
// glow moving) through the proxy, against those a 1° turn of the light changes.
TEST(LightProxy, ShadowEdgesMoveLessThanALightTurnOfOneDegree) {
  glContext();
  Renderer proxy, full;
  proxy.setMesh(denseSculpture());
  full.setMesh(denseSculpture());
  full.setLightProxyEnabled(false);
  Scene s = sceneOf(RenderMode::Marble);
  s.render.environment = Environment::None;  // the light's shadows and glow only
  const std::vector<bool> object = objectMask(full, s);
  const ImageRGBA8 withProxy = renderImage(proxy, s);
  const ImageRGBA8 withFull = renderImage(full, s);
  Scene turned = s;
  const float c = std::cos(glm::radians(1.0f)), sn = std::sin(glm::radians(1.0f));
  const glm::vec3 p = s.light.position;
  turned.light.position = glm::vec3(c * p.x + sn * p.z, p.y, -sn * p.x + c * p.z);
  const ImageRGBA8 withTurn = renderImage(full, turned);
  const double byProxy = changedFraction(withFull, withProxy, object);
  const double byTurn = changedFraction(withFull, withTurn, object);
  RecordProperty("changed_by_proxy", std::to_string(byProxy));
  RecordProperty("changed_by_1deg", std::to_string(byTurn));
  EXPECT_GT(byTurn, 0.002) << "negative control: a 1° light turn must move shadow edges";
  // 0.08 % when the proxy came (docs/performance.md), 0.17 % after session 22 (the hidden mirror
  // reads the light's layers, which the proxy draws), 0.24 % since session 23 (receivers behind a
  // part read them for the bounce's way through that part's stone: bounce_through_stone.glsl; the
  // changed pixels do not move with its tolerances), 0.32 % since session 25 (the further bounces'
  // patches are simplified from the proxy where there is one, 0.24 %; the bisected self-reflection
  // reads the other parts' light where the ray meets them, 0.27 %; together 0.32 %). The bound is
  // relative first: a quarter of a 1° turn's (3.6 %).
  EXPECT_LT(byProxy, 0.004);
  EXPECT_LT(byProxy, byTurn / 4.0);
}

// The light's proxy made on a worker thread (the viewer): frames drawn before it is there use the
// full mesh for the light's pass; once it is there the renderer is not current. Then the further
// bounces' form factors, made from the proxy on a worker thread too: frames drawn before they are
// there have none; once they are there the renderer is not current again, and the next frame
// equals, bit for bit, a renderer that made both in the foreground.
namespace {

// The dense sculpture in a renderer that makes its proxy and further bounces in the background.
void startInTheBackground(Renderer& background) {
  background.setLightProxyInBackground(true);
  background.setMesh(denseSculpture());
}

}  // namespace

TEST(LightProxy, MadeInTheBackgroundGivesTheSameStillFrame) {
  glContext();
  Scene s = sceneOf(RenderMode::Marble);
  OffscreenTarget target(kSize, kSize);
  Renderer background;
  startInTheBackground(background);
  const bool pendingAtFirstFrame = background.lightProxyPending();
  Renderer::FrameToken shown = background.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  const ImageRGBA8 first = target.read();
  const bool firstUsedFullMesh = background.lightTriangleCount() == background.triangleCount();
  // As the viewer's loop: a frame whenever the renderer says the shown one is no longer current.
  bool sawFurtherPending = false;
  for (int i = 0; i < 6000; ++i) {
    sawFurtherPending = sawFurtherPending || background.furtherBouncesPending();
    if (!background.lightProxyPending() && !background.furtherBouncesPending() &&
        background.isCurrent(s, glm::mat4(1.0f), shown, kSize, kSize))
      break;
    if (!background.isCurrent(s, glm::mat4(1.0f), shown, kSize, kSize))
      shown = background.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
    else
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_FALSE(background.lightProxyPending());
  EXPECT_FALSE(background.furtherBouncesPending());
  EXPECT_TRUE(sawFurtherPending) << "the form factors were made on the worker thread";
  EXPECT_LT(background.lightTriangleCount(), background.triangleCount());
  const ImageRGBA8 still = target.read();

  Renderer atOnce;
  atOnce.setMesh(denseSculpture());
  EXPECT_FALSE(atOnce.lightProxyPending());
  EXPECT_EQ(atOnce.lightTriangleCount(), background.lightTriangleCount());
  EXPECT_EQ(atOnce.lightProxyErrorUnits(), background.lightProxyErrorUnits());
  const ImageRGBA8 reference = renderImage(atOnce, s);
  EXPECT_TRUE(still.pixels == reference.pixels) << "mean difference " << meanAbsDiff(still, reference);
  // The first frame, drawn before the proxy and the further bounces were there, differs from the
  // finished picture: the negative control of the comparison above.
  EXPECT_TRUE(pendingAtFirstFrame);
  EXPECT_TRUE(firstUsedFullMesh);
  EXPECT_FALSE(first.pixels == reference.pixels);
}

// The viewer's scripted screenshot: waitForBackgroundWork() takes the pending proxy and has the next
// frame make the further bounces at once, so that frame is the finished picture.
TEST(LightProxy, WaitingForTheBackgroundWorkGivesTheFinishedFrame) {
  glContext();
  Scene s = sceneOf(RenderMode::Marble);
  OffscreenTarget target(kSize, kSize);
  Renderer background;
  startInTheBackground(background);
  background.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  background.waitForBackgroundWork();
  background.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  EXPECT_FALSE(background.lightProxyPending());
  EXPECT_FALSE(background.furtherBouncesPending());
  const ImageRGBA8 finished = target.read();
  Renderer atOnce;
  atOnce.setMesh(denseSculpture());
  const ImageRGBA8 reference = renderImage(atOnce, s);
  EXPECT_TRUE(finished.pixels == reference.pixels) << "mean difference " << meanAbsDiff(finished, reference);
}

// Interaction detail: frames while the camera orbits drawn from the copy, then the first still
// frame from the full mesh -- equal, bit for bit, to a fresh renderer's frame.
TEST(InteractionDetail, StillFrameEqualsAFreshRender) {
  glContext();
  Renderer moving;
  moving.setMesh(denseSculpture());
  ASSERT_LT(moving.interactionTriangleCount(), moving.triangleCount());
  Scene s = sceneOf(RenderMode::Marble);
  OffscreenTarget target(kSize, kSize);
  moving.setMeshDetail(Renderer::MeshDetail::Interaction);
  Scene orbiting = s;
  for (int i = 0; i < 3; ++i) {
    const float a = glm::radians(4.0f * float(3 - i));
    const glm::vec3 p = s.camera.position;
    orbiting.camera.position = glm::vec3(std::cos(a) * p.x + std::sin(a) * p.z, p.y, -std::sin(a) * p.x + std::cos(a) * p.z);
    moving.render(orbiting, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  }
  const Renderer::FrameToken arrived = moving.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);  // still the copy
  const ImageRGBA8 lastMoving = target.read();
  moving.setMeshDetail(Renderer::MeshDetail::Full);  // the first still frame
  EXPECT_FALSE(moving.isCurrent(s, glm::mat4(1.0f), arrived, kSize, kSize));
  moving.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  const ImageRGBA8 still = target.read();
  Renderer fresh;
  fresh.setMesh(denseSculpture());
  const ImageRGBA8 reference = renderImage(fresh, s);
  ASSERT_EQ(still.pixels.size(), reference.pixels.size());
  EXPECT_TRUE(still.pixels == reference.pixels) << "mean difference " << meanAbsDiff(still, reference);
  // Negative control: the moving frame at the same camera was drawn from the copy.
  EXPECT_FALSE(lastMoving.pixels == reference.pixels);
}

// The viewer's policy, object turning: the same holds when the model matrix moves.
TEST(InteractionDetail, StillFrameAfterTheObjectTurnedEqualsAFreshRender) {
  glContext();
  Renderer moving;
  moving.setMesh(denseSculpture());
  const Scene s = sceneOf(RenderMode::Marble);
  OffscreenTarget target(kSize, kSize);
  moving.setMeshDetail(Renderer::MeshDetail::Interaction);
  for (int i = 0; i < 3; ++i) {
    const glm::mat4 model = glm::rotate(glm::mat4(1.0f), glm::radians(5.0f * float(3 - i)), glm::vec3(0, 1, 0));
    moving.render(s, model, target.fbo(), kSize, kSize);
  }
  moving.setMeshDetail(Renderer::MeshDetail::Full);
  moving.render(s, glm::mat4(1.0f), target.fbo(), kSize, kSize);
  const ImageRGBA8 still = target.read();
  Renderer fresh;
  fresh.setMesh(denseSculpture());
  EXPECT_TRUE(still.pixels == renderImage(fresh, s).pixels);
}
