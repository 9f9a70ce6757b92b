// The subsurface blur spreads the light by the diffusion profile's distance *along the surface*
// (shaders/subsurface_blur.frag.glsl: the taps drawn in by sqrt(1 + s^2) where the view depth
// rises s mm per mm of screen). A plate lit from -x at 30 degrees of elevation behind a wall: the wall's shadow
// ends on the plate at a straight edge along z, and the blur carries the lit side's light across
// it over a width set by the stone's profile (the white stone at 150 mm per unit: a few
// pixels). Seen from straight above and from 70 degrees off the plate's normal (the camera turned
// about the edge's line, so the edge's profile runs along the slanted screen axis), the width
// measured along the plate must be the same. Without the correction the slanted view spreads the
// profile up to 1 / cos 70 = 2.9 times too far along the plate. Measured, 10-90 % widths: 0.026
// from above, 0.028 at 70 degrees (1.08); with main's blur (the negative control: the shader's
// correction removed, the tests rebuilt, since they embed the shaders) 0.026 and 0.044 (1.69),
// failing. The rest of the width is the shadow map's filter and the pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <initializer_list>
#include <utility>
#include <vector>

#include "gl_support.h"
#include "image_probe.h"
#include "plate_and_wall.h"
#include "principled_stone.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr float kElevationDeg = 25.0f;
constexpr float kWallX = -0.7f, kWall = 0.4f;

const PlateAndWall kPlate{kWallX, kWall, kElevationDeg};

// The camera `tiltDeg` off the plate's normal toward +x, 3 units from the shadow's end.
Scene plateScene(float tiltDeg, float fovDeg) {
  Scene s = grazingLightSeenFromAbove("test:plate-and-wall", kPlate.shadowEnd(), kElevationDeg, fovDeg);
  s.mm_per_unit = 150.0f;
  s.render.width = s.render.height = 256;
  const float t = glm::radians(tiltDeg);
  s.camera.position = s.camera.target + 3.0f * glm::vec3(std::sin(t), std::cos(t), 0.0f);
  s.material.roughness = 1.0f;  // no highlight in the way
  return s;
}

// The distance along the plate (x) over which the light rises from 10 % to 90 % of the way from
// the shadow to the lit plate, scanned in 0.002-unit steps (the shadow 0.86 units long: the dark
// reference over half a unit from the wall, whose lit top must stay out of the picture of the edge).
float edgeWidth(float tiltDeg, float fovDeg) {
  const Scene s = plateScene(tiltDeg, fovDeg);
  Renderer r;
  r.setMesh(kPlate.mesh());
  renderImage(r, s);
  const ImageRGBF img = r.readHdr();
  auto luma = [&](float x) { return glm::dot(linearRgbAround(img, s, {x, 0.0f, 0.0f}), glm::vec3(0.2126f, 0.7152f, 0.0722f)); };
  const float lit = luma(kPlate.shadowEnd() + 0.3f), dark = luma(kPlate.shadowEnd() - 0.3f);
  EXPECT_GT(lit, 4.0f * dark) << "lit " << lit << ", shadowed " << dark;
  float a = NAN, b = NAN;
  for (float x = kPlate.shadowEnd() - 0.3f; x <= kPlate.shadowEnd() + 0.3f; x += 0.002f) {
    const float f = (luma(x) - dark) / (lit - dark);
    if (std::isnan(a) && f >= 0.1f) a = x;
    if (std::isnan(b) && f >= 0.9f) b = x;
  }
  return b - a;
}

}  // namespace

TEST(BlurAlongSurface, TheEdgesSpreadIsTheSameSeenAtASlant) {
  HeadlessContext& context = glContext();
  (void)context;
  const float straight = edgeWidth(0.0f, 20.0f);
  // Zoomed so that a pixel covers about as much of the plate along x as from above.
  const float slanted = edgeWidth(70.0f, 8.0f);
  std::cout << "[          ] 10-90 % width along the plate: from above " << straight << ", at 70 degrees " << slanted
            << " (ratio " << slanted / straight << ")\n";
  ASSERT_GT(straight, 0.01f);  // the profile spans several pixels (0.004 units per pixel from above)
  EXPECT_NEAR(slanted / straight, 1.0f, 0.25f);
}

// The light the blur carries past the shadow's edge is the random walk's, whose far tail is red
// (src/marble/render/subsurface_profile.h; docs/quality.md, "Eighteenth session: the side-lit
// shade"): 10 mm into the shadow (the plate seen from above), the share of each channel's lit level
// that arrives there (above the shadow's level 45 mm in, beyond the walk's reach) is red's 0.6 % and
// blue's 0.04 % past a sharp edge (the walk of tools/walk_profile.cpp in this stone, one side of
// the axis beyond 10 mm), spread by the shadow map's filter. Asked: red at least 0.2 % and at
// least 4 times blue. Measured: red 0.63 %, green 0.18 %, blue 0.06 % (10x) when written; on session
// 26's main (and session 25's) red 0.37 %, green and blue at the shadow's own level (-0.004 %,
// -0.09 %). With the kernel cut at
// 6.51 mm, main's reach before session 18 (the negative control: subsurfaceReachMm forced to 6.51 and
// rebuilt), nothing arrives there in any channel: the shade neutral and dark, where Cycles' is red.
namespace {
// The flat plate's shadow edge (plateScene(0, 20), seen from above): for each distance in mm into
// the shadow, the share of each channel's lit level that arrives there, above the shadow's level
// 45 mm in (beyond the walk's reach).
std::vector<glm::vec3> flatEdgeShares(std::initializer_list<float> mmIntoShadow) {
  const Scene s = plateScene(0.0f, 20.0f);
  Renderer r;
  r.setMesh(kPlate.mesh());
  renderImage(r, s);
  const ImageRGBF img = r.readHdr();
  const float unitsPerMm = 1.0f / s.mm_per_unit;
  auto at = [&](float mm) { return linearRgbAround(img, s, {kPlate.shadowEnd() - mm * unitsPerMm, 0.0f, 0.0f}); };
  const glm::vec3 lit = linearRgbAround(img, s, {kPlate.shadowEnd() + 0.3f, 0.0f, 0.0f});
  const glm::vec3 dark = at(45.0f);
  std::vector<glm::vec3> shares;
  for (float mm : mmIntoShadow) shares.push_back((at(mm) - dark) / (lit - dark));
  return shares;
}
}  // namespace

TEST(BlurAlongSurface, TheShadePastTheEdgeTakesTheWalksRedTail) {
  HeadlessContext& context = glContext();
  (void)context;
  const glm::vec3 share = flatEdgeShares({10.0f})[0];
  std::cout << "[          ] 10 mm into the shadow, share of the lit level: " << share.r << " " << share.g << " "
            << share.b << "\n";
  EXPECT_GT(share.r, 0.002f);
  EXPECT_GT(share.r, 4.0f * std::max(share.b, 1e-6f));
}

// The blur reads the profile at a tap's distance in 3D, not along the screen alone
// (shaders/subsurface_blur.frag.glsl, SubsurfaceKernel::decayPerMm). A step seen from straight
// above: a wall 10 mm tall and 10 mm thick standing on the plate (100 mm per unit), lit from -x at
// 15 degrees, so that its top is lit and the plate past its +x face lies in its shadow for 37 mm.
// On screen the lit top and the shadowed plate touch, but 10 mm of depth lie between them: light
// entering the top's edge leaves the plate 2 mm past the wall's foot after sqrt(10^2 + 2^2) =
// 10.2 mm through the stone, not 2 mm. Asked: the share of the top's level (above the shadow's
// level 20 mm past the foot, beyond the walk's 16.2 mm reach from both the wall and the shadow's
// end) that arrives 2 mm past the foot, in every channel at most half of what arrives 2 mm into
// the shadow of a flat edge (TheShadePastTheEdgeTakesTheWalksRedTail's plate, whose lit side is as
// near on screen and on the same surface). What does arrive is also the light through the 10 mm
// wall (the transmission) and the bounce, not the blur's alone. Measured: 0.028 / 0.012 / 0.006
// (r / g / b) against the flat edge's 0.132 / 0.102 / 0.086 (0.21 / 0.12 / 0.07 of it); with the
// blur's taps weighed at their screen offset (the negative control: the shader's fall-off
// turned off, the tests rebuilt) 0.088 / 0.054 / 0.035 (0.67 / 0.53 / 0.41): fails in red and green.
TEST(BlurAlongSurface, LightDoesNotSpreadDownAStepAsIfItWereFlat) {
  HeadlessContext& context = glContext();
  (void)context;
  const PlateAndWall step{-0.3f, 0.1f, 15.0f};
  const float foot = step.wallX;  // the wall's +x face; the shadow runs from here to shadowEnd()
  Scene s = grazingLightSeenFromAbove("test:step", foot, step.elevationDeg, 10.0f);
  s.mm_per_unit = 100.0f;
  s.render.width = s.render.height = 256;
  s.material.roughness = 1.0f;  // no highlight in the way
  Renderer r;
  r.setMesh(step.mesh());
  renderImage(r, s);
  const ImageRGBF img = r.readHdr();
  const float unitsPerMm = 1.0f / s.mm_per_unit;
  const glm::vec3 top = linearRgbAround(img, s, {foot - 5.0f * unitsPerMm, step.height, 0.0f});
  const glm::vec3 dark = linearRgbAround(img, s, {foot + 20.0f * unitsPerMm, 0.0f, 0.0f});
  const glm::vec3 near = linearRgbAround(img, s, {foot + 2.0f * unitsPerMm, 0.0f, 0.0f});
  const glm::vec3 share = (near - dark) / (top - dark);

  // The flat edge, 2 and 10 mm into its shadow (the scene of TheShadePastTheEdgeTakesTheWalksRedTail).
  const std::vector<glm::vec3> flat = flatEdgeShares({2.0f, 10.0f});
  const glm::vec3 flat2 = flat[0], flat10 = flat[1];
  std::cout << "[          ] 2 mm past a 10 mm step's foot, share of the top's level: " << share.r << " " << share.g
            << " " << share.b << " (top " << top.r << ", there " << near.r << ", shadow " << dark.r
            << "); a flat edge 2 mm into its shadow: " << flat2.r << " " << flat2.g << " " << flat2.b
            << ", 10 mm: " << flat10.r << " " << flat10.g << " " << flat10.b << "\n";
  EXPECT_GT(top.r, 4.0f * dark.r);  // the top is lit, the plate beside it shadowed
  for (int c = 0; c < 3; ++c) EXPECT_LT(share[c], 0.5f * flat2[c]) << "channel " << c;
}

// A tap the blur leaves out (off the stone, or across a silhouette) gives its weight to the
// centre's own light, not to the other taps (shaders/subsurface_blur.frag.glsl; docs/quality.md,
// "Twenty-sixth session: the blur's left-out taps"). The plate of the tests above with its wall
// moved so that the shadow ends 3 mm before the plate's own +x edge: a lit strip 3 mm wide along
// the edge, background past it. Midway across the strip (1.5 mm from the edge and from the
// shadow) the light must be at least what it is on the unbounded plate 1.5 mm past its shadow's
// edge: light entering the strip cannot leave past the edge, where there is no stone (in the
// walk it turns back into the strip). Renormalised over the taps left on the plate, the kernel
// turned one-sided at the edge and took its missing half from the shadow's side. Measured
// (r / g / b): 0.3402 / 0.3467 / 0.3339 against the open plate's 0.3391 / 0.3443 / 0.3310;
// with the taps left out and renormalised (the negative control: main's blur, the tests
// rebuilt, by hand) 0.3244 / 0.3379 / 0.3287: fails in every channel.
TEST(BlurAlongSurface, AnEdgeKeepsTheLightThatEntersBesideIt) {
  HeadlessContext& context = glContext();
  (void)context;
  const Scene f = plateScene(0.0f, 10.0f);
  const float fu = 1.0f / f.mm_per_unit;
  const float shadowEnd = 1.0f - 3.0f * fu;
  const PlateAndWall strip{shadowEnd - kWall / std::tan(glm::radians(kElevationDeg)), kWall, kElevationDeg};
  Scene s = grazingLightSeenFromAbove("test:strip", 1.0f, kElevationDeg, 10.0f);
  s.mm_per_unit = f.mm_per_unit;
  s.render.width = s.render.height = 256;
  s.material.roughness = 1.0f;  // no highlight in the way
  Renderer r;
  r.setMesh(strip.mesh());
  renderImage(r, s);
  const glm::vec3 edge = linearRgbAround(r.readHdr(), s, {1.0f - 1.5f * fu, 0.0f, 0.0f});

  Renderer rf;
  rf.setMesh(kPlate.mesh());
  renderImage(rf, f);
  const ImageRGBF flat = rf.readHdr();
  const glm::vec3 open = linearRgbAround(flat, f, {kPlate.shadowEnd() + 1.5f * fu, 0.0f, 0.0f});
  std::cout << "[          ] midway across a 3 mm lit strip at the plate's edge: " << edge.r << " " << edge.g << " " << edge.b
            << "; the open plate 1.5 mm past its shadow's edge: " << open.r << " " << open.g << " " << open.b << "\n";
  for (int c = 0; c < 3; ++c) EXPECT_GE(edge[c], open[c]) << "channel " << c;
}

// A tap on a face that turns more from the camera than the centre's covers more surface than
// the centre's texels do, and weighs by it (shaders/subsurface_blur.frag.glsl, blur_tap: "the
// surface this tap stands for"; docs/quality.md, "Twenty-seventh session: ... the blur's taps
// weighed by the surface they cover"). A slab 40 mm thick (100 mm per unit) lit from -x at 25
// degrees: its top is lit, its +x face turned from the light. The light that reaches the +x face
// just below the edge entered the top and crossed the edge inside the stone: how much arrives
// does not depend on where the camera stands. Seen from +x 10 degrees above the top's plane (the
// top at a grazing 10 degrees, each of its texels 5.8 times the surface of one of the face's) and
// from 45 degrees, the light there is compared, in the bands 0.5-1.5 mm and 1.5-3 mm below the
// edge. (No transmission, so that only the blur carries light round the edge: the
// transmission's share there depends on whether the camera sees its entry.) The screen-space
// blur stays far from view-independent here: the grazing top's taps lie 3-6 times their nominal
// distance away in 3D, where the measure fades out (it cannot tell that fold from a step). So
// what is asked is the measure's share: the grazing view's light over the oblique one's, the
// channels' mean, at least 0.265 in the first band and 0.42 in the second. Measured: 0.277 /
// 0.291 / 0.302 (r / g / b) and 0.413 / 0.476 / 0.529; with every tap weighed by the centre's
// surface (the negative control: a = 1 in blur_tap, the tests rebuilt, by hand) 0.238 / 0.249 /
// 0.258 and 0.340 / 0.393 / 0.438: fails in both bands.
namespace {
glm::vec3 belowTheLitEdge(float viewDeg, float mmFrom, float mmTo) {
  Mesh m;
  addBox(m, {-1.0f, -0.2f, -1.0f}, {1.0f, 0.2f, 1.0f});
  computeVertexNormals(m, 60.0f);  // flat faces
  const glm::vec3 edge{1.0f, 0.2f, 0.0f};
  Scene s = grazingLightSeenFromAbove("test:slab", edge.x, kElevationDeg, 4.0f);
  s.mm_per_unit = 100.0f;
  s.render.width = s.render.height = 256;
  s.material.roughness = 1.0f;  // no highlight in the way
  s.material.translucency = 0.0f;
  const float t = glm::radians(viewDeg);
  s.camera.target = edge;
  s.camera.position = edge + 3.0f * glm::vec3(std::cos(t), std::sin(t), 0.0f);
  s.camera.up = {0.0f, 1.0f, 0.0f};
  Renderer r;
  r.setMesh(m);
  renderImage(r, s);
  const ImageRGBF img = r.readHdr();
  // The mean over a band of the face (every 0.05 mm from mmFrom to mmTo below the edge): the
  // blur's taps on the grazing top land at a different place for each row, so single rows vary.
  glm::vec3 sum(0.0f);
  int n = 0;
  for (float mm = mmFrom; mm <= mmTo + 1e-4f; mm += 0.05f, ++n)
    sum += linearRgbAround(img, s, edge - glm::vec3(0.0f, mm / s.mm_per_unit, 0.0f));
  return sum / float(n);
}
}  // namespace

TEST(BlurAlongSurface, AGrazingFaceRoundAConvexEdgeWeighsByItsSurface) {
  HeadlessContext& context = glContext();
  (void)context;
  for (auto [from, to] : {std::pair{0.5f, 1.5f}, std::pair{1.5f, 3.0f}}) {
    const glm::vec3 grazing = belowTheLitEdge(10.0f, from, to), oblique = belowTheLitEdge(45.0f, from, to);
    const glm::vec3 ratio = grazing / oblique;
    std::cout << "[          ] " << from << "-" << to << " mm below the lit edge: top seen at 10 degrees " << grazing.r << " "
              << grazing.g << " " << grazing.b << ", at 45 degrees " << oblique.r << " " << oblique.g << " "
              << oblique.b << " (ratio " << ratio.r << " " << ratio.g << " " << ratio.b << ")\n";
    EXPECT_GT(oblique.g, 0.0f);
    const float share = (ratio.r + ratio.g + ratio.b) / 3.0f;
    EXPECT_GT(share, from < 1.0f ? 0.265f : 0.42f) << from << "-" << to << " mm below the edge";
  }
}
