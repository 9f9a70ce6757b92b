// The light entering the stone is shadowed where the occluder puts the shadow, also on a surface
// the light grazes (shaders/shadow_receiver_plane.glsl; sessions 12-24 marble_shading.glsl's
// shadow_lookup_along_light). A plate lit from -x
// at 6 degrees of elevation (N.L = 0.105) behind a low wall: the wall's top edge (height kWall,
// at x = kWallX) ends the shadow at x = kWallX + kWall / tan(6 deg) on the plate. A lookup pushed
// out along the plate's normal by 2 texels of the light's map (marble before session 12) sees
// over the wall from 2 texels up, so the shadow ended up to 2 texels / tan(6 deg) = 0.064 units
// too soon (measured: at 0.205 for 0.251, the negative control, shader edited and rebuilt);
// looked up along the light it ended at 0.253; each texel compared with the receiver's plane
// (session 25) at 0.261, the lookup no longer moved half a texel along N, which at this slant
// moved it ~0.016 along the plate. The wall's other side gets no light,
// and the camera looks straight down at the shadow's end. The highlight is shadowed by the
// along-the-light lookup (bilinear_visibility): a black, rough stone shows it alone, and its
// shadow must end there too (the back-lit glints, docs/quality.md "Twenty-fifth session: the
// highlight's shadow").
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "gl_support.h"
#include "image_probe.h"
#include "plate_and_wall.h"
#include "principled_stone.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr float kElevationDeg = 6.0f;
constexpr float kWallX = -0.7f, kWall = 0.1f;

const PlateAndWall kPlate{kWallX, kWall, kElevationDeg};

Scene grazingScene() {
  Scene s = grazingLightSeenFromAbove("test:plate-and-wall", kPlate.shadowEnd(), kElevationDeg, 20.0f);
  s.mm_per_unit = 1000.0f;  // the blur's millimetres far below the distances here
  return s;
}

// Where the shadow ends on the plate, scanned in 0.004-unit steps (half a pixel): the first x
// whose luma is halfway between the lit and the shadowed plate's.
float shadowEndSeen(const Scene& s) {
  Renderer r;
  r.setMesh(kPlate.mesh());
  renderImage(r, s);
  const ImageRGBF img = r.readHdr();
  auto luma = [&](float x) { return glm::dot(linearRgbAround(img, s, {x, 0.0f, 0.0f}), glm::vec3(0.2126f, 0.7152f, 0.0722f)); };
  const float lit = luma(kPlate.shadowEnd() + 0.3f), dark = luma(kPlate.shadowEnd() - 0.3f);
  EXPECT_GT(lit, 4.0f * dark) << "lit " << lit << ", shadowed " << dark;
  if (!(lit > 4.0f * dark)) return NAN;
  float crossing = NAN;
  for (float x = kPlate.shadowEnd() - 0.25f; x <= kPlate.shadowEnd() + 0.25f; x += 0.004f)
    if (luma(x) >= 0.5f * (lit + dark)) {
      crossing = x;
      break;
    }
  std::cout << "[          ] shadow ends at " << crossing << ", the occluder puts it at " << kPlate.shadowEnd() << "\n";
  return crossing;
}

}  // namespace

TEST(GrazingShadow, EndsWhereTheOccluderPutsIt) {
  HeadlessContext& context = glContext();
  (void)context;
  const float crossing = shadowEndSeen(grazingScene());
  ASSERT_FALSE(std::isnan(crossing));
  // The filter's reach (the 4 taps' bilinear span, 2 texels of the 1024 map over 2 sqrt(3) units)
  // is 0.034 units along the plate at this slant; allowed 0.03 either way.
  EXPECT_NEAR(crossing, kPlate.shadowEnd(), 0.03f);
}

// The highlight alone: the stone black (nothing enters it, no retro-reflection), roughness 0.6 so
// the lobe reaches the camera overhead (the half vector 42 degrees off the plate's normal). Its
// lookup, one bilinear comparison (half the filter's reach: 0.017 units here), is held to the same
// 0.03: it ends at 0.245 for 0.251; looked up along N (before session 25: the negative control,
// shader edited and rebuilt) at 0.205, failing.
TEST(GrazingShadow, TheHighlightsShadowEndsThereToo) {
  HeadlessContext& context = glContext();
  (void)context;
  Scene s = grazingScene();
  s.material.base_color = s.material.vein_color = s.material.vein2_color = glm::vec3(0.0f);
  s.material.roughness = 0.6f;
  const float crossing = shadowEndSeen(s);
  ASSERT_FALSE(std::isnan(crossing));
  EXPECT_NEAR(crossing, kPlate.shadowEnd(), 0.03f);
}
