// The transmission where the light's map finds no stone between the inward-offset exit and the
// light (a zero chord): the light enters at the exit's own cosine, max(N.L, 0), not at the cosine
// the map's four texels hold (entry_cosine in shaders/lighting.frag.glsl). The case of teapot-back's
// and teapot-side's lid crack: the teapot's body is an open sheet, the light reaches its inner side
// through the gap between lid and body, and the points on its outer side, facing away from the
// light, read their own sheet as the entry at a zero chord; with the map's cosine they glowed at
// the full transport T(0) (teapot-back 0.075-0.088 linear, Cycles 0.006-0.020; docs/quality.md,
// "Twenty-sixth session: the zero chord's cosine"). Here: an open square sheet (no thickness, no
// stone for the walk to cross) seen from the front and lit from behind at 37 degrees. The light
// leaving its front must be a small share of what the same sheet gives lit from the front at the
// same angle (its direct light): measured 0.008 with the change, 0.94 without it (negative control,
// checked by hand: entry_cosine returning s_cos.y, rebuilt: the test fails).
#include <gtest/gtest.h>

#include <iostream>

#include "gl_support.h"
#include "principled_stone.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 64;

// One square, x and y in [-1, 1], facing +z (the camera), open: no back, no sides.
Mesh openSheet() {
  Mesh m;
  m.positions = {{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}};
  m.indices = {0, 1, 2, 0, 2, 3};
  computeVertexNormals(m, 60.0f);
  return m;
}

// The sheet's light, linear luma summed over the middle half of the picture (the sheet covers it).
double middleLight(float lightZ) {
  Scene s = backLitScene("test:sheet", 40.0f, kSize);
  s.light.position = {0.6f, 0.0f, lightZ};
  Renderer renderer;
  renderer.setMesh(openSheet());
  renderImage(renderer, s);
  const ImageRGBF img = renderer.readHdr();
  double sum = 0.0;
  for (int y = kSize / 4; y < 3 * kSize / 4; ++y)
    for (int x = kSize / 4; x < 3 * kSize / 4; ++x) {
      const float* p = &img.pixels[3 * (static_cast<size_t>(y) * img.width + x)];
      sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    }
  return sum;
}

struct TransmissionZeroChord : ::testing::Test {
  HeadlessContext& context = glContext();
};

}  // namespace

TEST_F(TransmissionZeroChord, AnOpenSheetLitFromBehindDoesNotGlowAtTheMapsCosine) {
  const double front = middleLight(0.8f);
  const double behind = middleLight(-0.8f);
  ASSERT_GT(front, 0.0);
  std::cout << "[          ] lit from behind / lit from the front: " << behind / front << "\n";
  EXPECT_LT(behind / front, 0.05);
}
