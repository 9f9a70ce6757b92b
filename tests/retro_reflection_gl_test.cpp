// The `marble` mode's retro-reflection (shaders/principled_entry.glsl, principled_retro; added by the
// post pass, marble_retro_reflected): Cycles 3.4's Principled BSDF adds, beside the random walk, a
// diffuse closure of the subsurface weight with the BRDF albedo / pi * RR (F_L + F_V + F_L F_V (RR - 1)),
// RR = roughness (1 + L.V) (kernel/closure/bssrdf.h, bssrdf_setup; bsdf_principled_diffuse.h). It is
// reflected at the surface and grows where the camera grazes a lit face. Measured on the linear HDR
// image.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "gl_support.h"
#include "image_probe.h"

using namespace marble;
using namespace marble::test;

namespace {

// The cube's front face (normal +z) lit head-on by a directional light (N.L = 1, F_L = 0) and seen
// from `view_deg` off its normal. ior 1 reflects nothing (the exact Fresnel factor is 0: no
// highlight, no mirror terms), so the roughness changes nothing but the retro-reflection, and
// with F_L = 0 the lobe is RR F_V: the reflected radiance is albedo * I * RR * F_V (E = pi I).
Scene faceScene(float view_deg, float roughness) {
  Scene s;
  s.mesh = "builtin:cube";
  s.render.width = s.render.height = 96;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  const float v = glm::radians(view_deg);
  s.camera.position = glm::vec3(std::sin(v), 0.0f, std::cos(v)) * 20.0f + glm::vec3(0, 0, 1);
  s.camera.target = {0, 0, 1};
  s.camera.fov_y_deg = 6;
  s.light.type = LightType::Directional;
  s.light.position = {0.0f, 0.0f, 1.0f};
  Material& m = s.material;
  m.base_color = m.vein_color = m.vein2_color = glm::vec3(0.5f);
  m.ior = 1.0f;
  m.roughness = roughness;
  return s;
}

float greenAtFace(Renderer& r, const Scene& s) {
  renderImage(r, s);
  return linearRgbAround(r.readHdr(), s, {0, 0, 1}).g;
}

}  // namespace

// Seen 75 degrees off the normal: L.V = cos 75, RR = 1.259 at roughness 1, F_V = (1 - cos 75)^5 =
// 0.224, so roughness 1 adds 0.5 * 0.2815 = 0.141 of radiance to what roughness 0 shows (the lit
// face itself: 0.5 * (1 - F_L / 2) = 0.5). Without the lobe the two renders are the same picture.
TEST(RetroReflection, TheCameraGrazingALitFaceSeesCyclesLobe) {
  HeadlessContext& context = glContext();
  (void)context;
  Renderer renderer;
  renderer.setMesh(builtinMesh("cube"));
  const double c = std::cos(glm::radians(75.0));
  const double fv = std::pow(1.0 - c, 5.0), rr = 1.0 * (1.0 + c);
  const double expected = 0.5 * rr * fv;
  const float rough = greenAtFace(renderer, faceScene(75.0f, 1.0f));
  const float smooth = greenAtFace(renderer, faceScene(75.0f, 0.0f));
  EXPECT_NEAR(rough - smooth, expected, 0.05 * expected) << "roughness 1: " << rough << ", roughness 0: " << smooth;
  std::cout << "[          ] grazing view: lobe " << rough - smooth << " (expected " << expected << "), face " << smooth
            << "\n";
}

// Seen and lit head-on (F_L = F_V = 0) the lobe is 0: the roughness changes nothing.
TEST(RetroReflection, NoneSeenAndLitHeadOn) {
  HeadlessContext& context = glContext();
  (void)context;
  Renderer renderer;
  renderer.setMesh(builtinMesh("cube"));
  const float rough = greenAtFace(renderer, faceScene(0.0f, 1.0f));
  const float smooth = greenAtFace(renderer, faceScene(0.0f, 0.0f));
  EXPECT_NEAR(rough - smooth, 0.0, 1e-4 * smooth) << "roughness 1: " << rough << ", roughness 0: " << smooth;
}
