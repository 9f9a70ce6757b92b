// The `marble` mode's light: a point light falls off as 1/d² around the distance d0 at which its
// intensity is defined (the light's distance to the scene centre), a directional light does not;
// and --hdr's alpha is coverage. Measured on the linear HDR image (Renderer::readHdr).
//
// The set-up makes the radiance of the cube's front face (z = +1) a closed form: a flat albedo ρ,
// ior 1 (F0 = 0: no specular), the Principled entry weight 1 − (1 − cosθ)^5 / 2 (issue 15;
// shaders/marble_light.glsl), roughness 1, no environment, no translucency, a camera far along +z.
// Then
//   L = ρ · E · cosθ · (1 − (1 − cosθ)^5 / 2) / π,  E = π I (d0 / d)²  for a point light.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "gl_support.h"
#include "image_probe.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 128;
constexpr float kAlbedo = 0.8f;

Scene faceScene() {
  Scene s;
  s.mesh = "builtin:cube";
  s.render.width = s.render.height = kSize;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  s.camera.position = {0, 0, 8};
  s.camera.target = {0, 0, 0};
  s.camera.fov_y_deg = 20;
  Material& m = s.material;
  m.base_color = m.vein_color = m.vein2_color = glm::vec3(kAlbedo);
  m.ior = 1.0f;
  m.roughness = 1.0f;
  m.translucency = 0.0f;
  return s;
}

// The mean linear green value of the 3x3 pixels around where world point p lands.
// The green channel around p (image_probe.h).
float radianceAt(const ImageRGBF& img, const Scene& s, glm::vec3 p) { return linearRgbAround(img, s, p).g; }

// The closed form above, per unit intensity, for a point on the face seen head-on.
float expectedRadiance(float irradianceOverPi, float cosTheta) {
  return kAlbedo * irradianceOverPi * cosTheta * (1.0f - 0.5f * std::pow(1.0f - cosTheta, 5.0f));
}

ImageRGBF renderHdr(Renderer& r, const Scene& s) {
  renderImage(r, s);
  return r.readHdr();
}

struct LightFalloff : ::testing::Test {
  HeadlessContext& context = glContext();
  Renderer renderer;
  LightFalloff() { renderer.setMesh(builtinMesh("cube")); }
};

// A and B on the front face: A right under the light (d = 1, cosθ = 1), B 1.2 to the side.
const glm::vec3 kA{-0.6f, 0.0f, 1.0f}, kB{0.6f, 0.0f, 1.0f};

}  // namespace

TEST_F(LightFalloff, PointLightFallsOffAsInverseSquare) {
  Scene s = faceScene();
  s.light.type = LightType::Point;
  s.light.position = {-0.6f, 0.0f, 2.0f};
  const ImageRGBF img = renderHdr(renderer, s);
  const float d0 = glm::length(s.light.position);  // 2.088: where intensity 1 means E = π
  const float dA = glm::distance(s.light.position, kA), dB = glm::distance(s.light.position, kB);
  const float cosB = 1.0f / dB;  // the light is 1 unit above the face
  const float a = radianceAt(img, s, kA), b = radianceAt(img, s, kB);
  // Absolute, at A: (d0/dA)² = 4.36 times what intensity 1 gives at d0.
  EXPECT_NEAR(a, expectedRadiance((d0 / dA) * (d0 / dA), 1.0f), 0.03f * a);
  // The near/far ratio: (dA/dB)² · cosθ_B (1 − (1 − cosθ_B)^5 / 2) = 0.262. Without the falloff
  // it would be the cosine alone, 0.637.
  const float expected = (dA / dB) * (dA / dB) * cosB * (1.0f - 0.5f * std::pow(1.0f - cosB, 5.0f));
  EXPECT_NEAR(b / a, expected, 0.03f * expected) << "A " << a << " B " << b;
  std::cout << "[          ] point: A " << a << " (expected " << expectedRadiance((d0 / dA) * (d0 / dA), 1.0f)
            << "), B/A " << b / a << " (expected " << expected << ")\n";
}

TEST_F(LightFalloff, IrradianceIsPiTimesIntensityAtTheSceneCentresDistance) {
  // Head-on, at two distances: E/π = (d0/d)², d0 = the light's distance to the origin.
  Scene s = faceScene();
  s.light.position = {0.0f, 0.0f, 3.0f};
  const float near = radianceAt(renderHdr(renderer, s), s, {0, 0, 1});  // d = 2, d0 = 3
  s.light.position = {0.0f, 0.0f, 6.0f};
  const float far = radianceAt(renderHdr(renderer, s), s, {0, 0, 1});   // d = 5, d0 = 6
  EXPECT_NEAR(near, expectedRadiance(9.0f / 4.0f, 1.0f), 0.03f * near);
  EXPECT_NEAR(far, expectedRadiance(36.0f / 25.0f, 1.0f), 0.03f * far);
  std::cout << "[          ] head-on: d 2 " << near << " (expected " << expectedRadiance(9.0f / 4.0f, 1.0f) << "), d 5 " << far
            << " (expected " << expectedRadiance(36.0f / 25.0f, 1.0f) << ")\n";
}

TEST_F(LightFalloff, DirectionalLightHasNone) {
  Scene s = faceScene();
  s.light.type = LightType::Directional;
  s.light.position = {0.0f, 0.0f, 1.0f};  // from +z: cosθ = 1 all over the face
  const ImageRGBF img = renderHdr(renderer, s);
  const float a = radianceAt(img, s, kA), b = radianceAt(img, s, kB);
  EXPECT_NEAR(a, expectedRadiance(1.0f, 1.0f), 0.02f * a);
  EXPECT_NEAR(b / a, 1.0f, 0.02f) << "A " << a << " B " << b;
  std::cout << "[          ] directional: A " << a << " (expected " << expectedRadiance(1.0f, 1.0f) << "), B/A " << b / a << "\n";
}

TEST_F(LightFalloff, HdrAlphaIsCoverageEvenWhereNothingIsLit) {
  // The light off and no environment: every pixel is exactly 0, yet the sphere covers the picture.
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = faceScene();
  s.mesh = "builtin:sphere";
  s.light.intensity = 0.0f;
  s.camera.position = {0, 0, 4};
  s.camera.fov_y_deg = 40;
  const ImageRGBF img = renderHdr(renderer, s);
  ASSERT_EQ(img.alpha.size(), static_cast<size_t>(kSize) * kSize);
  for (float v : img.pixels) ASSERT_EQ(v, 0.0f);
  double covered = 0;
  for (float a : img.alpha) {
    ASSERT_TRUE(a == 0.0f || a == 1.0f);
    covered += a;
  }
  // A unit sphere seen from 4 units: a disc of angular radius asin(1/4); the image spans 40°.
  const double r = std::tan(std::asin(0.25)) / std::tan(glm::radians(20.0)) * kSize / 2;
  EXPECT_NEAR(covered, M_PI * r * r, 0.03 * M_PI * r * r);
  EXPECT_EQ(img.alpha[static_cast<size_t>(kSize / 2) * kSize + kSize / 2], 1.0f);  // centre
  EXPECT_EQ(img.alpha[0], 0.0f);                                                  // corner
}
