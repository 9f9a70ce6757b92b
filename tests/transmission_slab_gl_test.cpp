// The `marble` mode's transmission at its absolute level (dipole_transport in
// shaders/lighting.frag.glsl): through a wide flat slab lit evenly from behind, what leaves the
// face away from the light, seen head-on, must read albedo · I · T(s) with the closed form
//   T(s) = (z_r e^(-σtr d_r)/d_r + z_v e^(-σtr d_v)/d_v) / (e^(-σtr z_r) + e^(-σtr z_v)),
//   d = sqrt(s² + z²)   (Jensen et al. 2001's R_d integrated over a plane s away, over its total)
// computed here from the material's coefficients on the CPU: no direct light reaches that face, no
// environment, and the Principled entry weight is 1 at normal incidence. A wrong normalization,
// entry weight, falloff or unit (mm against scene units) would each miss it by far more than 6 %.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "gl_support.h"
#include "image_probe.h"
#include "marble/mesh/vertex_normals.h"
#include "marble/render/view_setup.h"
#include "marble/scene/material_scattering.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 128;
constexpr float kHalfWidth = 1.0f, kHalfThickness = 0.1f;  // the slab, scene units
constexpr float kMmPerUnit = 50.0f;                        // 100 mm wide, 10 mm thick

// A box 2 x 2 x 0.2, hard-edged (the crease splits its faces).
Mesh slab() {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.positions.push_back({(i & 1) ? kHalfWidth : -kHalfWidth, (i & 2) ? kHalfWidth : -kHalfWidth,
                           (i & 4) ? kHalfThickness : -kHalfThickness});
  // Quads wound counter-clockwise seen from outside: -z, +z, -y, +y, -x, +x.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
    for (int t : {0, 1, 2, 0, 2, 3}) m.indices.push_back(static_cast<uint32_t>(q[t]));
  computeVertexNormals(m, 60.0f);
  return m;
}

Scene slabScene() {
  Scene s;
  s.mesh = "test:slab";
  s.mm_per_unit = kMmPerUnit;
  s.render.width = s.render.height = kSize;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  s.camera.position = {0, 0, 6};
  s.camera.target = {0, 0, 0};
  s.camera.fov_y_deg = 22;
  s.light.type = LightType::Directional;
  s.light.position = {0, 0, -1};  // from behind: the light travels along +z
  s.light.intensity = 1.0f;
  Material& m = s.material;
  m.base_color = m.vein_color = m.vein2_color = glm::vec3(0.87f, 0.85f, 0.8f);
  m.subsurface_radius_mm = {17.0f, 12.0f, 8.0f};
  m.scattering = ScatteringForm::Radius;
  m.ior = 1.5f;
  m.roughness = 0.15f;
  resolveScattering(m);
  return s;
}

// The stone the transmission crosses at the face's centre: the slab, less the exit point's inward
// offset of two light-map texels (shaders/lighting.frag.glsl; the renderer's 1024² map spans the
// bounding sphere's diameter), 0.34 mm here: 3-11 % more light through 10 mm, channel by channel.
float crossedMm() {
  const float texelWorld = 2.0f * kBoundingRadius / 1024.0f;
  return (2.0f * kHalfThickness - 2.0f * texelWorld) * kMmPerUnit;
}

// T(s) above, per channel.
glm::vec3 slabTransport(const Material& m, float sMm) {
  const glm::vec3 sigma = transportCoefficientMm(m);
  const DipoleDepths z = dipoleDepthsMm(m);
  glm::vec3 t;
  for (int c = 0; c < 3; ++c) {
    const float dr = std::sqrt(sMm * sMm + z.zr_mm[c] * z.zr_mm[c]);
    const float dv = std::sqrt(sMm * sMm + z.zv_mm[c] * z.zv_mm[c]);
    const float through = z.zr_mm[c] * std::exp(-sigma[c] * dr) / dr + z.zv_mm[c] * std::exp(-sigma[c] * dv) / dv;
    t[c] = through / (std::exp(-sigma[c] * z.zr_mm[c]) + std::exp(-sigma[c] * z.zv_mm[c]));
  }
  return t;
}

struct TransmissionSlab : ::testing::Test {
  HeadlessContext& context = glContext();
  Renderer renderer;
  TransmissionSlab() { renderer.setMesh(slab()); }
  ImageRGBF render(const Scene& s) {
    renderImage(renderer, s);
    return renderer.readHdr();
  }
};

}  // namespace

TEST_F(TransmissionSlab, WideSlabGivesTheDipolesClosedForm) {
  const Scene s = slabScene();
  const ImageRGBF img = render(s);
  const glm::vec3 centre = linearRgbAround(img, s, {0, 0, kHalfThickness});
  const glm::vec3 expected = s.material.base_color * slabTransport(s.material, crossedMm());
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(expected[c], 1e-4f) << "the slab must let some light through in channel " << c;
    EXPECT_NEAR(centre[c], expected[c], 0.06f * expected[c]) << "channel " << c;
  }
  std::cout << "[          ] centre " << centre.r << " " << centre.g << " " << centre.b << ", closed form " << expected.r << " "
            << expected.g << " " << expected.b << "\n";
}

TEST_F(TransmissionSlab, PointLightFarAwayGivesTheSame) {
  // A point light 12 units behind: the entry irradiance is I (d0/d)² with d0 = 12 and d = 11.9;
  // over the taps' reach (under 1 unit) the falloff and slant change it by under 1 %.
  Scene s = slabScene();
  s.light.type = LightType::Point;
  s.light.position = {0, 0, -12};
  const ImageRGBF img = render(s);
  const glm::vec3 centre = linearRgbAround(img, s, {0, 0, kHalfThickness});
  const float falloff = (12.0f / (12.0f - kHalfThickness)) * (12.0f / (12.0f - kHalfThickness));
  const glm::vec3 expected =
      falloff * s.material.base_color * slabTransport(s.material, crossedMm());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], expected[c], 0.06f * expected[c]) << "channel " << c;
}
