// The `marble` mode's further bounces (the radiosity's grid, src/marble/render/further_radiosity.h,
// added by the bounce pass's merge) at their absolute level in the renderer's picture, in the fold
// of fold_view_factors.h: a lit plate (light straight down) and a wall standing on it. The wall's
// face toward the plate gets no direct light, only the plate's first bounce; the plate then gets
// that back: the second bounce, which the light's map cannot give (its emitter, the wall's face, is
// not lit). The plate's radiance with the wall, less without it, is (the plate re-emits albedo x E,
// E = PI at normal incidence: radiance a; the stone takes diffuse light in at 41/42)
//   L2(x) = a^3 (41/42)^2 twoBounceIntegral(d).
// Neglected: the plate's fourth bounce (a^2 f f' of the second: ~0.1 of it here) and what the
// plate's specular layer mirrors of the wall (F0 0.04). At 1000 mm per unit the subsurface blur
// reaches ~0.02 units. Measured (session 25, the radiosity): 1.13 and 1.14 of L2 at 0.15 and 0.3
// from the wall (the radiosity alone, further_radiosity_test.cpp: 0.997 and 0.988 of G_2). Allowed
// 35 % (as the screen-space gather before it, sessions 13-24: 0.95 and 1.10). Controls (by hand):
// the merge without the further bounces, 0.12 and 0.13 of L2 (fails).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "box_mesh.h"
#include "fold_view_factors.h"
#include "gl_support.h"
#include "image_probe.h"
#include "principled_stone.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;
using namespace marble::test::fold;

namespace {

constexpr float kAlbedo = 0.8f;


Scene foldScene() {
  Scene s;
  s.mesh = "test:fold";
  s.mm_per_unit = 1000.0f;
  s.render.width = s.render.height = 256;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  // Looking into the fold at 45 degrees: the camera sees the wall's face and the plate alike.
  s.camera.position = {kWall + 2.0f, kPlateTop + 2.0f, 0.0f};
  s.camera.target = {kWall + 0.3f, kPlateTop + 0.3f, 0.0f};
  s.camera.fov_y_deg = 40;
  s.light.type = LightType::Directional;
  s.light.position = {0.0f, 1.0f, 0.0f};  // straight down: the wall's face is edge-on to it
  s.light.intensity = 1.0f;
  s.material = test::principledStone(glm::vec3(kAlbedo));
  return s;
}

}  // namespace

TEST(BounceFurther, TheFoldsPlateGetsItsLightBackFromTheWall) {
  HeadlessContext& context = glContext();
  (void)context;
  const Scene s = foldScene();
  const HdrPair img = renderHdrPair(s, foldMesh(true), foldMesh(false));
  const ImageRGBF& a = img.first;
  const ImageRGBF& b = img.second;
  for (float d : {0.15f, 0.3f}) {
    const glm::vec3 got = linearRgbAround(a, s, probe(d)) - linearRgbAround(b, s, probe(d));
    const double expected = std::pow(kAlbedo, 3.0) * (41.0 / 42.0) * (41.0 / 42.0) * twoBounceIntegral(d);
    std::cout << "[          ] d " << d << ": expected " << expected << ", got " << got.g << " ("
              << got.g / expected << ")\n";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected, 0.35 * expected) << "d " << d << " channel " << c;
  }
}

namespace {

// A block 0.06 thick standing on the plate across the fold, 0.03 to 0.09 before the probe at 0.3
// from the wall, 0.15 high: every way from the probe to the wall's face below y = 0.9 runs through it.
constexpr float kBlockedProbe = 0.3f;

Mesh withBlock(bool withWall) {
  Mesh m = foldMesh(withWall);
  const float x1 = kWall + kBlockedProbe - 0.03f;
  addBox(m, {x1 - 0.06f, kPlateTop, -1.0f}, {x1, kPlateTop + 0.15f, 1.0f});
  computeVertexNormals(m, 60.0f);
  return m;
}

}  // namespace

TEST(BounceFurther, NoneFromTheWallThroughABlockBesideTheProbe) {
  // The wall's light at the probe (the picture with the wall less without it), with the block in the
  // way against without the block: the block can only take light away (its faces the probe sees
  // face away from the wall). The radiosity's rays stop at the block (further_radiosity.h: the
  // form factors by rays through the patches' BVH). Measured (session 25) 0.30 of the unobstructed
  // light; with the screen-space gather before it 0.55, and without its occlusion test 1.99 (the
  // block's faces re-emitting what the wall sends them, through the block), which fails.
  HeadlessContext& context = glContext();
  (void)context;
  Scene s = foldScene();
  s.render.width = s.render.height = 1024;
  const HdrPair open = renderHdrPair(s, foldMesh(true), foldMesh(false));
  const HdrPair blocked = renderHdrPair(s, withBlock(true), withBlock(false));
  const glm::vec3 p = probe(kBlockedProbe);
  const glm::vec3 fromTheWall = linearRgbAround(open.first, s, p) - linearRgbAround(open.second, s, p);
  const glm::vec3 throughTheBlock = linearRgbAround(blocked.first, s, p) - linearRgbAround(blocked.second, s, p);
  std::cout << "[          ] the wall's light at the probe " << fromTheWall.g << ", through the block "
            << throughTheBlock.g << " (" << throughTheBlock.g / fromTheWall.g << ")\n";
  for (int c = 0; c < 3; ++c) EXPECT_LT(throughTheBlock[c], 0.8f * fromTheWall[c]) << "channel " << c;
}
