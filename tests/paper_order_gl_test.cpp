// The paper's order switch (§4) changes the `paper` mode's picture by exactly what its formula
// says, for both ways of meeting the Schlick term (schlick_blend). With the subsurface term s
// (per channel), the albedo C, S = s C (the `subsurface` mode), the Schlick term F (the
// `reflectance` mode; at metalness 0 it does not depend on the colour it is given) and k = k_schlick:
//   opacity (the paper's text):   sss-first mix(sC, F, k), schlick-first mix(C, F, k) s
//                                 difference  k F (1 - s),       times C: k F (C - S)
//   program (the paper's code):   sss-first sC - k(1 - F), schlick-first (C - k(1 - F)) s
//                                 difference -k (1 - F)(1 - s),  times C: -k (1 - F)(C - S)
// So the switch changes nothing where no light was lost inside (s = 1) and most where much was;
// under the program's subtraction about (1 - F) / F (here 6-24) times as much as under opacity.
// Measured on the linear HDR image (half floats) of a sphere lit from the side.
#include <gtest/gtest.h>

#include <cmath>

#include "gl_support.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 64;

Scene sphereScene(RenderMode mode, SchlickBlend blend, ShadingOrder order, float kSchlick) {
  Scene s;
  s.mesh = "builtin:sphere";
  s.render.width = s.render.height = kSize;
  s.render.mode = mode;
  s.render.antialias = Antialias::None;
  s.light.position = glm::vec3(3.0f, 0.5f, -1.5f);  // from the side: the thickness varies over the picture
  s.material.metalness = 0.0f;
  s.material.k_schlick = kSchlick;
  s.material.schlick_blend = blend;
  s.material.order = order;
  return s;
}

ImageRGBF render(Renderer& r, const Scene& s) {
  renderImage(r, s);
  return r.readHdr();
}

struct OrderCheck {
  double meanSwitch = 0;     // mean |sss-first - schlick-first| over the object's pixels and channels
  double meanExpected = 0;   // mean |the formula's difference|, divided by C as measured
  double worstError = 0;     // max |C (P1 - P2) - expected C (P1 - P2)|
  double meanError = 0;
  int pixels = 0;
};

OrderCheck checkOrder(SchlickBlend blend, float k) {
  glContext();
  Renderer renderer;
  renderer.setMesh(builtinMesh("sphere"));
  const ImageRGBF C = render(renderer, sphereScene(RenderMode::Albedo, blend, ShadingOrder::SubsurfaceFirst, k));
  const ImageRGBF S = render(renderer, sphereScene(RenderMode::Subsurface, blend, ShadingOrder::SubsurfaceFirst, k));
  const ImageRGBF F = render(renderer, sphereScene(RenderMode::Reflectance, blend, ShadingOrder::SubsurfaceFirst, k));
  const ImageRGBF P1 = render(renderer, sphereScene(RenderMode::Paper, blend, ShadingOrder::SubsurfaceFirst, k));
  const ImageRGBF P2 = render(renderer, sphereScene(RenderMode::Paper, blend, ShadingOrder::ReflectanceFirst, k));
  OrderCheck out;
  for (size_t i = 0; i < P1.alpha.size(); ++i) {
    if (P1.alpha[i] < 1.0f || P2.alpha[i] < 1.0f || C.alpha[i] < 1.0f) continue;  // the object's inside only
    ++out.pixels;
    for (size_t c = 0; c < 3; ++c) {
      const size_t j = 3 * i + c;
      const double lost = C.pixels[j] - S.pixels[j];  // C (1 - s)
      const double expected = blend == SchlickBlend::Opacity ? k * F.pixels[j] * lost : -k * (1.0 - F.pixels[j]) * lost;
      const double measured = C.pixels[j] * (P1.pixels[j] - P2.pixels[j]);
      out.meanSwitch += std::abs(P1.pixels[j] - P2.pixels[j]);
      out.meanExpected += std::abs(expected) / std::max(C.pixels[j], 1e-3f);
      out.meanError += std::abs(measured - expected);
      out.worstError = std::max(out.worstError, std::abs(measured - expected));
    }
  }
  const double n = 3.0 * std::max(out.pixels, 1);
  out.meanSwitch /= n;
  out.meanExpected /= n;
  out.meanError /= n;
  return out;
}

}  // namespace

TEST(PaperOrder, TheSwitchChangesThePictureByTheFormulasDifference) {
  for (SchlickBlend blend : {SchlickBlend::Opacity, SchlickBlend::Program}) {
    const OrderCheck r = checkOrder(blend, 0.5f);
    const char* name = blend == SchlickBlend::Opacity ? "opacity" : "program";
    ASSERT_GT(r.pixels, kSize * kSize / 4) << name;
    // Half-float images: about 5e-4 per value, a few values per pixel.
    EXPECT_LT(r.worstError, 4e-3) << name;
    EXPECT_LT(r.meanError, 0.1 * r.meanExpected) << name;
    EXPECT_NEAR(r.meanSwitch, r.meanExpected, 0.1 * r.meanExpected) << name;
    EXPECT_GT(r.meanSwitch, blend == SchlickBlend::Opacity ? 1e-3 : 2e-2) << name << ": the switch shows";
  }
}

TEST(PaperOrder, WithoutTheSchlickTermTheOrderChangesNothing) {
  // Negative control: k_schlick 0 leaves the subsurface term alone, whichever comes first.
  for (SchlickBlend blend : {SchlickBlend::Opacity, SchlickBlend::Program}) {
    const OrderCheck r = checkOrder(blend, 0.0f);
    EXPECT_LT(r.meanSwitch, 1e-6);
  }
}
