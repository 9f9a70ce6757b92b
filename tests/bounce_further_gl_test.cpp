// The `marble` mode's further bounces (shaders/bounce_further.frag.glsl) at their absolute level, in
// a fold: a lit plate (light straight down) and a wall standing on it. The wall's face toward the
// plate gets no direct light, only the plate's first bounce; the plate then gets that back: the
// second bounce, which the light's map cannot give (its emitter, the wall's face, is not lit). The
// plate's radiance with the wall, less without it, is (the plate re-emits albedo x E, E = PI at
// normal incidence: radiance a; the stone takes diffuse light in at 41/42)
//   L2(x) = a^3 (41/42)^2 ∫_wall f(y) cosθ_y cosθ_x / (π r²) dA_y,
//   f(y) = ∫_plate cosθ_p cosθ_y / (π r²) dA_p,
// the analytic two-bounce radiosity of the fold, integrated here on the CPU (the wall's face on a
// 48 x 48 grid, f at each point on 100 x 200: converged to 1 %). Neglected: the plate's fourth
// bounce (a^2 f f' of the second: ~0.1 of it here) and what the plate's specular layer mirrors of
// the wall (F0 0.04). At 1000 mm per unit the subsurface blur reaches ~0.02 units.
// Measured (session 13): the screen-space second bounce alone 0.73 and 0.83 of L2 at 0.15 and 0.3
// from the wall, with the series for the later bounces 1.07 and 1.13 (the series assumes a
// neighbourhood that re-emits its own further bounce, ~1.3x here, where the fold's fourth bounce is
// ~1.1x). Allowed 35 %. Controls (shader edited, rebuilt): further bounces off, 0 (fails); the
// first version (samples snapped to the pass's texels, four rings over a quarter of the frame, the
// first bounce's softened law), 0.51 and 0.42 with the series (fails); four angles per ring
// instead of eight, 1.71 at 0.15 (fails). Since session 21 (the further bounces' grid evened out
// over its 2 x 2 blocks, bounce_deinterleave.frag.glsl): 0.95 and 1.10 (before it 1.02 and 1.14).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "box_mesh.h"
#include "gl_support.h"
#include "image_probe.h"
#include "principled_stone.h"
#include "marble/mesh/vertex_normals.h"
#include "marble/render/bounce_pass.h"
#include "marble/render/subsurface_blur_pass.h"

using namespace marble;
using namespace marble::test;

namespace {

// The wall: x in [-kWall, kWall], y in [kPlateTop, 1]; the plate: y in [kPlateTop - 0.2,
// kPlateTop], x in [kWall, 1]; both z in [-1, 1] (bounce_gl_test.cpp's corner).
constexpr float kWall = 0.1f, kPlateTop = -0.6f;
constexpr float kAlbedo = 0.8f;
// A point on the plate's top, d from the wall's face.
glm::vec3 probe(float d) { return {kWall + d, kPlateTop, 0.0f}; }

Mesh fold(bool withWall) {
  Mesh m;
  if (withWall) addBox(m, {-kWall, kPlateTop, -1.0f}, {kWall, 1.0f, 1.0f});
  addBox(m, {kWall, kPlateTop - 0.2f, -1.0f}, {1.0f, kPlateTop, 1.0f});
  computeVertexNormals(m, 60.0f);  // flat faces
  return m;
}

Scene foldScene() {
  Scene s;
  s.mesh = "test:fold";
  s.mm_per_unit = 1000.0f;
  s.render.width = s.render.height = 256;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  // Looking into the fold at 45 degrees: the camera sees the wall's face and the plate alike (the
  // further bounces' emitters are the surfaces the camera sees).
  s.camera.position = {kWall + 2.0f, kPlateTop + 2.0f, 0.0f};
  s.camera.target = {kWall + 0.3f, kPlateTop + 0.3f, 0.0f};
  s.camera.fov_y_deg = 40;
  s.light.type = LightType::Directional;
  s.light.position = {0.0f, 1.0f, 0.0f};  // straight down: the wall's face is edge-on to it
  s.light.intensity = 1.0f;
  s.material = test::principledStone(glm::vec3(kAlbedo));
  return s;
}

// f(y, z): the plate's top face's view factor from the wall's face at (kWall, y, z).
double plateSeenFromWall(double y, double z) {
  const int nx = 100, nz = 200;
  const double dx = (1.0 - kWall) / nx, dz = 2.0 / nz;
  double sum = 0.0;
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k) {
      const double ux = (i + 0.5) * dx, uy = kPlateTop - y, uz = -1.0 + (k + 0.5) * dz - z;  // wall -> plate
      const double r2 = ux * ux + uy * uy + uz * uz;
      sum += ux * -uy / (r2 * r2 * M_PI);  // cosθ_y cosθ_p / (π r²), the cosines as dots over r
    }
  return sum * dx * dz;
}

// ∫_wall f(y) cosθ_y cosθ_x / (π r²) dA_y at the plate's point d from the wall.
double twoBounceIntegral(float d) {
  const int ny = 48, nz = 48;
  const double dy = (1.0 - kPlateTop) / ny, dz = 2.0 / nz;
  double sum = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int k = 0; k < nz; ++k) {
      const double y = kPlateTop + (j + 0.5) * dy, z = -1.0 + (k + 0.5) * dz;
      const double ux = -d, uy = y - kPlateTop, uz = z;  // plate point -> wall point
      const double r2 = ux * ux + uy * uy + uz * uz;
      sum += plateSeenFromWall(y, z) * (-ux) * uy / (r2 * r2 * M_PI);
    }
  return sum * dy * dz;
}

}  // namespace

TEST(BounceFurther, TheFoldsPlateGetsItsLightBackFromTheWall) {
  HeadlessContext& context = glContext();
  (void)context;
  const Scene s = foldScene();
  const HdrPair img = renderHdrPair(s, fold(true), fold(false));
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

TEST(BounceFurther, TheInterleavedTurnsAreEvenedOutBetweenNeighbouringTexels) {
  // The fold's plate again, its further bounces alone (with the wall, less without: the wall's face
  // is lit only by the plate's first bounce). The further bounces' gather turns its pattern per 2 x 2
  // block of its grid as the first bounce's does (bounce_further.frag.glsl), and at a texel's own
  // pixel (twice the bounce pass's scale) the merge's and the lighting's upsamples take that texel
  // alone. The pass evens the turns out over the blocks with the first bounce's draw
  // (bounce_deinterleave.frag.glsl), so a texel's value lies near the tent-weighted mean of its
  // 3 x 3 neighbours (the plate is flat: they all match). Measured: the RMS of (texel - that mean)
  // relative to the texels' mean, over the plate's texels from 0.1 to 0.8 from the wall (132 at
  // 512²): 0.040; without the evening out (the merge reading the gather's grid, each texel its own
  // turn) 0.080, which fails. Part of the residual is the field's own curvature near the wall.
  HeadlessContext& context = glContext();
  (void)context;
  Scene s = foldScene();
  s.render.width = s.render.height = 512;
  const HdrPair img = renderHdrPair(s, fold(true), fold(false));
  const int scale = 2 * bounceScale(subsurfaceScale(s.render));  // the further bounces' grid
  const int n = s.render.width / scale;
  // Each texel's own pixel (GL counts rows from the bottom), its point on the plate's plane, and
  // its further bounces; texels off the plate's middle marked NaN.
  const CameraMatrices cam = cameraMatrices(s.camera, 1.0f);
  std::vector<double> v(static_cast<size_t>(n) * n, std::nan(""));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int px = i * scale, py = j * scale;
      const glm::vec2 ndc = (glm::vec2(px, py) + 0.5f) / glm::vec2(s.render.width, s.render.height) * 2.0f - 1.0f;
      const glm::vec4 nearP = cam.invViewProj * glm::vec4(ndc, -1.0f, 1.0f), farP = cam.invViewProj * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 o = glm::vec3(nearP) / nearP.w, d = glm::vec3(farP) / farP.w - o;
      if (d.y >= 0.0f) continue;
      const glm::vec3 p = o + d * ((kPlateTop - o.y) / d.y);
      if (p.x < kWall + 0.1f || p.x > 0.8f || std::abs(p.z) > 0.7f) continue;
      const size_t at = (static_cast<size_t>(s.render.height - 1 - py) * s.render.width + px) * 3 + 1;  // green
      v[static_cast<size_t>(j) * n + i] = img.first.pixels[at] - img.second.pixels[at];
    }
  double sq = 0.0, mean = 0.0;
  int cells = 0;
  for (int j = 1; j < n - 1; ++j)
    for (int i = 1; i < n - 1; ++i) {
      double tent = 0.0;
      bool all = true;
      for (int b = -1; b <= 1; ++b)
        for (int a = -1; a <= 1; ++a) {
          const double x = v[static_cast<size_t>(j + b) * n + i + a];
          all = all && !std::isnan(x);
          tent += (2 - std::abs(a)) * (2 - std::abs(b)) * x / 16.0;
        }
      if (!all) continue;
      const double r = v[static_cast<size_t>(j) * n + i] - tent;
      sq += r * r;
      mean += v[static_cast<size_t>(j) * n + i];
      ++cells;
    }
  ASSERT_GT(cells, 20);
  const double relative = std::sqrt(sq / cells) / (mean / cells);
  std::cout << "[          ] " << cells << " texels, mean " << mean / cells
            << ", RMS of (texel - its neighbours' tent mean) / mean: " << relative << "\n";
  EXPECT_LT(relative, 0.06);
}

namespace {

// A block 0.06 thick standing on the plate across the fold, 0.03 to 0.09 before the probe at 0.3
// from the wall, 0.15 high: every way from the probe to the wall's face below y = 0.9 runs through it.
constexpr float kBlockedProbe = 0.3f;

Mesh withBlock(bool withWall) {
  Mesh m = fold(withWall);
  const float x1 = kWall + kBlockedProbe - 0.03f;
  addBox(m, {x1 - 0.06f, kPlateTop, -1.0f}, {x1, kPlateTop + 0.15f, 1.0f});
  computeVertexNormals(m, 60.0f);
  return m;
}

}  // namespace

TEST(BounceFurther, NoneFromTheWallThroughABlockBesideTheProbe) {
  // The wall's light at the probe (the picture with the wall less without it), with the block in the
  // way against without the block: the block can only take light away (its faces the probe sees
  // face away from the wall). The further bounces' samples take the first bounce's occlusion next
  // to the receiver (bounce_screen_occlusion.glsl, at an eighth of the way: from the probe, the
  // wall's face up to y = 0.6, most of its view factor). At 1024²: the further bounces' grid (16
  // pixels) fine enough that its texels around the probe have that point inside the block (at the
  // fold test's 256² they lie beyond it). Measured 0.55 of the unobstructed light; without the test
  // in bounce_further.frag.glsl (the first bounce's kept) 1.99 (the block's faces re-emit what the
  // wall sends them, through the block), which fails.
  HeadlessContext& context = glContext();
  (void)context;
  Scene s = foldScene();
  s.render.width = s.render.height = 1024;
  const HdrPair open = renderHdrPair(s, fold(true), fold(false));
  const HdrPair blocked = renderHdrPair(s, withBlock(true), withBlock(false));
  const glm::vec3 p = probe(kBlockedProbe);
  const glm::vec3 fromTheWall = linearRgbAround(open.first, s, p) - linearRgbAround(open.second, s, p);
  const glm::vec3 throughTheBlock = linearRgbAround(blocked.first, s, p) - linearRgbAround(blocked.second, s, p);
  std::cout << "[          ] the wall's light at the probe " << fromTheWall.g << ", through the block "
            << throughTheBlock.g << " (" << throughTheBlock.g / fromTheWall.g << ")\n";
  for (int c = 0; c < 3; ++c) EXPECT_LT(throughTheBlock[c], 0.8f * fromTheWall[c]) << "channel " << c;
}
