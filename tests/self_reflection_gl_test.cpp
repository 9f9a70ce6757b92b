// The stone's own light mirrored in its surface (shaders/self_reflection.glsl; docs/quality.md,
// "Eighteenth session: teapot-back and bunny-back"). A plate with a wall standing on it, the light
// from above at 45 degrees on the wall's side, the camera low over the plate looking at the wall:
// the plate's top, seen at a grazing angle, mirrors the wall's lit face. Its specular layer sends
// the camera F(N.V) times the wall's radiance there (a near-mirror at the stone's roughness 0.15),
// on top of the light the wall bounces onto the plate diffusely. The test isolates the mirror
// image by its dependence on the view: the plate's point p is seen from two heights, at N.V = 0.2
// and 0.45; the diffuse bounce it receives is the same from both, the mirrored light is
// F(0.2) L_w - F(0.45) L_w' more from the low one (L_w, L_w': the wall's radiance where the two
// mirror rays meet it, read off the same pictures). The gains are with the wall less without it.
// The bounce's own mirrored part (a wide Phong lobe from the light's map, bounce.glsl) is left out
// wherever the mirror ray meets the wall on screen, so the wall is mirrored once.
// Measured: 0.99 and 1.02 of the predicted difference at d = 0.3 and 0.45 (allowed 0.8-1.25).
// Controls, rebuilt by hand: main's (no self-reflection, the bounce's mirrored part everywhere)
// 0.35 and 0.44, failing; both at once (the mirrored part not left out; with the 16-step march of
// the first version) 1.31 and 1.72, failing -- the wall counted twice; a march reaching 0.43
// instead of 0.62 (10 steps x 1.68) 1.00 and 0.40, failing at 0.45, whose mirror ray is 0.48 long.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <iostream>

#include "box_mesh.h"
#include "fresnel_dielectric.h"
#include "gl_support.h"
#include "image_probe.h"
#include "principled_stone.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;

namespace {

using namespace marble::test::thin_plate;

// The camera on the plate's far side at N.V = cosView toward the plate's point at distance d from
// the wall, 1.5 away from it.
Scene plateScene(float d, float cosView) {
  Scene s;
  s.mesh = "test:plate-with-wall";
  s.mm_per_unit = 100.0f;
  s.render.width = s.render.height = 256;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  const glm::vec3 p{kWall + d, kPlateTop, 0.0f};
  const float sinView = std::sqrt(1.0f - cosView * cosView);
  s.camera.position = p + 1.5f * glm::vec3(sinView, cosView, 0.0f);
  s.camera.target = p;
  s.camera.fov_y_deg = 40;
  s.light.type = LightType::Directional;
  s.light.position = {1.0f, 1.0f, 0.0f};  // from above at 45 degrees, on the wall's face's side
  s.light.intensity = 1.0f;
  s.material = test::principledStone(glm::vec3(0.8f));
  return s;
}

struct Seen {
  float gain;      // at p, with the wall less without it (green)
  float mirrored;  // F(N.V) x the wall's radiance where p's mirror ray meets it (green)
};

// What the plate shows at d from the wall seen at cosView: the scene with and without the wall.
Seen seenWith(const Scene& s, const Mesh& withWall, const Mesh& withoutWall, float d, float cosView) {
  const HdrPair img = renderHdrPair(s, withWall, withoutWall);
  const glm::vec3 p{kWall + d, kPlateTop, 0.0f};
  // The mirror ray rises at cosView over the plate and meets the wall's face d further on.
  const float sinView = std::sqrt(1.0f - cosView * cosView);
  const glm::vec3 w{kWall, kPlateTop + d * cosView / sinView, 0.0f};
  const float gain = linearRgbAround(img.first, s, p).g - linearRgbAround(img.second, s, p).g;
  return {gain, static_cast<float>(fresnelDielectric(cosView, s.material.ior)) * linearRgbAround(img.first, s, w).g};
}

Seen seenFrom(float d, float cosView) {
  return seenWith(plateScene(d, cosView), plateWithWall(true), plateWithWall(false), d, cosView);
}

// The low view (cos 0.2) gains over the high one (cos 0.45) what it mirrors more of the wall, within
// [lo, hi] of the prediction, at each d.
template <class SeenAt>
void expectTheMirroredDifference(SeenAt seenAt, std::initializer_list<float> distances, float lo, float hi) {
  for (float d : distances) {
    const Seen low = seenAt(d, 0.2f), high = seenAt(d, 0.45f);
    const float predicted = low.mirrored - high.mirrored, measured = low.gain - high.gain;
    std::cout << "[          ] d " << d << ": gain low " << low.gain << ", high " << high.gain << "; mirrored low "
              << low.mirrored << ", high " << high.mirrored << ": measured / predicted " << measured / predicted
              << "\n";
    ASSERT_GT(predicted, 0.0f) << "the low view mirrors more of the wall";
    EXPECT_GT(measured / predicted, lo) << "d " << d;
    EXPECT_LT(measured / predicted, hi) << "d " << d;
  }
}

}  // namespace

TEST(SelfReflection, AGrazingViewMirrorsTheLitPartBeside) {
  HeadlessContext& context = glContext();
  (void)context;
  expectTheMirroredDifference(seenFrom, {0.3f, 0.45f}, 0.8f, 1.25f);
}

namespace {

// The plate and (or without) its wall, with a bar (along z) in front of the wall at 0.29-0.31 from
// its face and 0.37-0.385 over the plate: in the light from above at 45 degrees it shades the wall
// from about 0.065 to 0.09 over the plate, and nothing else the test reads.
Mesh plateWallAndBar(bool withWall) {
  Mesh m = plateWithWall(withWall);
  addBox(m, {kWall + 0.295f, kPlateTop + 0.37f, -1.0f}, {kWall + 0.305f, kPlateTop + 0.385f, 1.0f});
  computeVertexNormals(m, 60.0f);
  return m;
}

Seen seenBesideTheShade(float d, float cosView) {
  Scene s = plateScene(d, cosView);
  s.mm_per_unit = 1000.0f;  // the blur's reach (millimetres) well inside the shade's band
  return seenWith(s, plateWallAndBar(true), plateWallAndBar(false), d, cosView);
}

}  // namespace

TEST(SelfReflection, TheMirrorReadsTheWallWhereTheRayMeetsIt) {
  // As above, with the bar's shade on the wall from 0.065 to 0.09 over the plate: the plate must
  // mirror the wall where its mirror ray meets it, not where the march's first point behind the
  // wall lies. At d = 0.2 and 0.205 the low view's ray meets the wall 0.204 / 0.209 along, 0.041 /
  // 0.042 over the plate, just past the march's point at 0.201, so the next point, 0.352 along,
  // lies behind the wall 0.07 over the plate: in the shade. The high view's ray meets the wall at
  // 0.10 / 0.103 and its next point lies above the shade. Measured 0.86 and 0.82 of the predicted
  // difference (allowed 0.75-1.25); with the crossing not bisected (SELF_REFLECTION_REFINE 0, the
  // first point behind as before session 25; checked by hand) 0.64 and 0.59.
  HeadlessContext& context = glContext();
  (void)context;
  expectTheMirroredDifference(seenBesideTheShade, {0.2f, 0.205f}, 0.75f, 1.25f);
}
