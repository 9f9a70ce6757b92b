// Environment maps in the renderer, on the headless GL context: a uniform white map lights a
// sphere exactly like a constant ambient radiance of 1 would (diffuse and split-sum specular),
// a half-bright map lights the side facing it and turns with the rotation, and the texture is
// counted, replaced and freed.
#include <gtest/gtest.h>

#include <cmath>

#include "gl_support.h"
#include "hdr_support.h"
#include "marble/environment/environment_lighting.h"
#include "marble/environment/ggx_prefilter.h"
#include "marble/render/view_setup.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 128;

// A sphere facing the camera head-on, lit only by the environment, of one flat albedo.
Scene sphereScene() {
  Scene s;
  s.mesh = "builtin:sphere";
  s.render.width = s.render.height = kSize;
  s.render.mode = RenderMode::Marble;
  s.camera.position = {0, 0, 4};
  s.light.intensity = 0.0f;
  s.material.base_color = s.material.vein_color = s.material.vein2_color = glm::vec3(0.5f);
  s.material.ior = 1.5f;
  s.material.roughness = 0.3f;
  s.render.environment = Environment::Map;
  s.render.environment_map = "test";
  s.render.environment_intensity = 1.0f;
  return s;
}

struct EnvironmentFixture : ::testing::Test {
  HeadlessContext& context = glContext();
  Renderer renderer;
  EnvironmentFixture() { renderer.setMesh(builtinMesh("sphere")); }

  ImageRGBF renderHdr(const Scene& s) {
    renderImage(renderer, s);
    return renderer.readHdr();
  }
};

glm::vec3 hdrAt(const ImageRGBF& img, int x, int y) {
  const float* p = &img.pixels[(static_cast<size_t>(y) * img.width + x) * 3];
  return {p[0], p[1], p[2]};
}

// N.V where pixel (x, y) (row 0 the top) sees the unit sphere, or -1 off it.
float sphereNoV(const Scene& s, int x, int y) {
  const CameraMatrices cam = cameraMatrices(s.camera, 1.0f);
  const glm::vec2 ndc((x + 0.5f) / kSize * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kSize * 2.0f);
  const glm::vec4 far = cam.invViewProj * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - cam.position);
  const float b = glm::dot(cam.position, dir), c = glm::dot(cam.position, cam.position) - 1.0f;
  const float disc = b * b - c;
  if (disc < 0.0f) return -1.0f;
  const glm::vec3 p = cam.position + dir * (-b - std::sqrt(disc));
  return glm::dot(glm::normalize(p), -dir);
}

// shaders/marble_shading.glsl's env_brdf_approx (Karis 2014) for a grey F0.
float envBrdfApprox(float f0, float roughness, float NoV) {
  const glm::vec4 c0(-1.0f, -0.0275f, -0.572f, 0.022f), c1(1.0f, 0.0425f, 1.04f, -0.04f);
  const glm::vec4 r = roughness * c0 + c1;
  const float a004 = std::min(r.x * r.x, std::exp2(-9.28f * NoV)) * r.x + r.y;
  return f0 * (-1.04f * a004 + r.z) + (1.04f * a004 + r.w);
}

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Mean luminance of the sphere's pixels in columns [x0, x1).
float columnsMean(const ImageRGBF& img, const Scene& s, int x0, int x1) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = x0; x < x1; ++x)
      if (sphereNoV(s, x, y) > 0.2f) {
        sum += luminance(hdrAt(img, x, y));
        ++n;
      }
  return n ? static_cast<float>(sum / n) : 0.0f;
}

}  // namespace

TEST_F(EnvironmentFixture, UniformWhiteMapLightsLikeAConstantAmbientOfOne) {
  renderer.setEnvironmentMap(prefilterEnvironment(constantImage(64, 32, glm::vec3(1.0f)), "white"));
  const Scene s = sphereScene();
  const ImageRGBF img = renderHdr(s);
  // Radiance 1 from everywhere: irradiance / pi = 1 enters by the Principled coupling averaged
  // over the hemisphere (1 - 1/42, shaders/marble_light.glsl), is coloured by the albedo, and the
  // split sum reflects env_brdf_approx of it.
  const float f0 = 0.04f, albedo = 128.0f / 255.0f;  // the G-buffer stores 0.5 as 8 bits
  int checked = 0;
  for (int y = 4; y < kSize; y += 8)
    for (int x = 4; x < kSize; x += 8) {
      const float NoV = sphereNoV(s, x, y);
      if (NoV < 0.5f) continue;  // away from the silhouette, where the mesh's facets and the blur's edge matter
      const float expected = albedo * (41.0f / 42.0f) + envBrdfApprox(f0, s.material.roughness, NoV);
      const glm::vec3 got = hdrAt(img, x, y);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected, 0.01f * expected) << "pixel " << x << ", " << y << " N.V " << NoV;
      ++checked;
    }
  EXPECT_GT(checked, 60);
  // No direction is special: the four sides agree.
  const glm::vec3 l = hdrAt(img, 30, 64), r = hdrAt(img, 97, 64), t = hdrAt(img, 64, 30), b = hdrAt(img, 64, 97);
  for (const glm::vec3& v : {r, t, b}) EXPECT_NEAR(luminance(v), luminance(l), 0.01f * luminance(l));
}

TEST_F(EnvironmentFixture, HalfBrightMapLightsTheSideFacingItAndTurnsWithTheRotation) {
  // Radiance 1 from the +X half of the sky, nothing from the rest.
  renderer.setEnvironmentMap(prefilterEnvironment(
      imageFromDirections(128, 64, [](const glm::vec3& d) { return glm::vec3(d.x > 0.0f ? 1.0f : 0.0f); }), "half"));
  Scene s = sphereScene();
  ImageRGBF img = renderHdr(s);
  EXPECT_GT(columnsMean(img, s, 80, 128), 3.0f * columnsMean(img, s, 0, 48)) << "+X is to the right";
  s.render.environment_rotation_deg = 180.0f;
  img = renderHdr(s);
  EXPECT_GT(columnsMean(img, s, 0, 48), 3.0f * columnsMean(img, s, 80, 128)) << "turned half way round: left";
  // +90 turns the map's +X to -Z, behind the sphere: the side facing the camera goes dark;
  // -90 turns it to +Z, towards the camera.
  s.render.environment_rotation_deg = 90.0f;
  const float behind = luminance(hdrAt(renderHdr(s), 64, 64));
  s.render.environment_rotation_deg = -90.0f;
  const float front = luminance(hdrAt(renderHdr(s), 64, 64));
  EXPECT_GT(front, 3.0f * behind);
}

TEST_F(EnvironmentFixture, TheTextureIsCountedReplacedAndFreed) {
  Scene s = sphereScene();
  renderHdr(s);  // the passes' own targets exist from here on
  // ... and the programs specialized for a map (compiled at their first use, then kept).
  renderer.setEnvironmentMap(prefilterEnvironment(constantImage(64, 32, glm::vec3(0.5f)), "warm-up"));
  renderHdr(s);
  renderer.clearEnvironmentMap();
  const size_t before = renderer.glBytes();
  const long objects = gl::liveObjectCount();
  renderer.setEnvironmentMap(prefilterEnvironment(constantImage(64, 32, glm::vec3(1.0f)), "white"));
  // 64 x 32 and its levels down to 8 x 4 (alpha reaches 1 there), RGBA16F.
  ASSERT_EQ(prefilterLevelCount(64), 4);
  EXPECT_EQ(renderer.glBytes() - before, (64 * 32 + 32 * 16 + 16 * 8 + 8 * 4) * 8u);
  EXPECT_EQ(gl::liveObjectCount(), objects + 1);
  const ImageRGBF white = renderHdr(s);
  renderer.setEnvironmentMap(prefilterEnvironment(constantImage(64, 32, glm::vec3(1.0f, 0.0f, 0.0f)), "red"));
  EXPECT_EQ(gl::liveObjectCount(), objects + 1) << "the old texture is deleted";
  const ImageRGBF red = renderHdr(s);  // the same scene: the cached lighting must not be reused
  EXPECT_LT(hdrAt(red, 64, 64).g, 0.5f * hdrAt(white, 64, 64).g);
  renderer.clearEnvironmentMap();
  EXPECT_EQ(renderer.glBytes(), before);
  EXPECT_EQ(gl::liveObjectCount(), objects);
  // Asking for a map with none loaded gives no environment light, like "none".
  const ImageRGBF noMap = renderHdr(s);
  s.render.environment = Environment::None;
  const ImageRGBF none = renderHdr(s);
  EXPECT_EQ(noMap.pixels, none.pixels);
}

TEST_F(EnvironmentFixture, RougherSurfacesSeeABlurrierSun) {
  // A small sun straight behind the camera: a mirror-like sphere shows it as a small, intense
  // highlight at the centre; a rough one spreads it wide and dim.
  const glm::vec3 sun(0, 0, 1);
  const float cosR = std::cos(glm::radians(2.0f));
  renderer.setEnvironmentMap(prefilterEnvironment(
      imageFromDirections(512, 256, [&](const glm::vec3& d) { return glm::vec3(glm::dot(d, sun) > cosR ? 500.0f : 0.0f); }),
      "sun"));
  Scene s = sphereScene();
  s.material.base_color = s.material.vein_color = s.material.vein2_color = glm::vec3(0.0f);  // reflection only
  auto spread = [&](float roughness) {
    s.material.roughness = roughness;
    const ImageRGBF img = renderHdr(s);
    const float peak = luminance(hdrAt(img, 64, 64));
    int lit = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) lit += luminance(hdrAt(img, x, y)) > 0.1f * peak;
    return std::pair<float, int>(peak, lit);
  };
  const auto [sharpPeak, sharpArea] = spread(0.1f);
  const auto [roughPeak, roughArea] = spread(0.5f);
  EXPECT_GT(sharpPeak, 5.0f * roughPeak);
  EXPECT_GT(roughArea, 5 * sharpArea);
}
