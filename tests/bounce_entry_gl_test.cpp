// The first bounce that enters a thin part on its lit side and crosses it (shaders/bounce_entry.
// frag.glsl, bounce_entry.glsl; docs/quality.md, "Fifteenth session: teapot-back's indirect light
// is the parts' lit rims lighting each other"). A thin plate (5 mm at 100 mm per unit) with a wall
// standing on it, the light from above at 45 degrees on the wall's side: the wall's face and the
// plate's top are lit, and the wall's face sends light onto the plate's top. Seen from above, the
// plate's top gains that bounce (the camera-side gather); seen from below, its underside gains the
// same light carried through the plate's chord along the light (5 mm / cos 45), which the
// camera-side gather cannot give (the underside faces away from the wall). The gain below over the
// gain above is the slab's transport at that chord, T(s) (marble::slabTransportAt, the shader's
// own table), to within what the top's gain holds beside the first bounce: the further bounces
// (the plate and the wall seeing each other again) and the bounce the top's specular layer
// mirrors, both absent from the transmitted light.
// Measured: 0.84 and 0.97 of T(s) at 0.2 and 0.35 from the wall; allowed 0.6-1.25. Control (the
// crossing term removed from lighting.frag.glsl, rebuilt): 0.005 (fails).
#include <gtest/gtest.h>

#include <iostream>

#include "box_mesh.h"
#include "gl_support.h"
#include "image_probe.h"
#include "principled_stone.h"
#include "marble/mesh/vertex_normals.h"
#include "marble/scene/slab_transport.h"

using namespace marble;
using namespace marble::test;

namespace {

using namespace marble::test::thin_plate;

Scene plateScene(bool fromBelow) {
  Scene s;
  s.mesh = "test:plate-with-wall";
  s.mm_per_unit = 100.0f;
  s.render.width = s.render.height = 256;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  const float y = fromBelow ? kPlateTop - kPlate : kPlateTop;
  s.camera.position = {kWall + 1.2f, y + (fromBelow ? -1.6f : 1.6f), 0.0f};
  s.camera.target = {kWall + 0.3f, y, 0.0f};
  s.camera.fov_y_deg = 40;
  s.light.type = LightType::Directional;
  s.light.position = {1.0f, 1.0f, 0.0f};  // from above at 45 degrees, on the wall's face's side
  s.light.intensity = 1.0f;
  s.material = test::principledStone(glm::vec3(0.8f));
  return s;
}

// Radiance with the wall less without it at the plate's point d from the wall, on its top or its
// underside.
glm::vec3 gainFromTheWall(bool fromBelow, float d) {
  const Scene s = plateScene(fromBelow);
  const HdrPair img = renderHdrPair(s, plateWithWall(true), plateWithWall(false));
  const glm::vec3 p{kWall + d, fromBelow ? kPlateTop - kPlate : kPlateTop, 0.0f};
  return linearRgbAround(img.first, s, p) - linearRgbAround(img.second, s, p);
}

}  // namespace

TEST(BounceEntry, LightBouncedOntoAThinPartsLitSideCrossesIt) {
  HeadlessContext& context = glContext();
  (void)context;
  const Scene s = plateScene(true);
  const glm::vec3 T = slabTransportAt(slabTransportFor(s.material), kPlate * s.mm_per_unit / std::sqrt(0.5f));
  for (float d : {0.2f, 0.35f}) {
    const glm::vec3 above = gainFromTheWall(false, d), below = gainFromTheWall(true, d);
    std::cout << "[          ] d " << d << ": gain above " << above.g << ", below " << below.g << ", T " << T.g
              << ": below / (above T) " << below.g / (above.g * T.g) << "\n";
    ASSERT_GT(above.g, 0.0f) << "the wall lights the plate's top";
    for (int c = 0; c < 3; ++c) {
      const float ratio = below[c] / (above[c] * T[c]);
      EXPECT_GT(ratio, 0.6f) << "d " << d << " channel " << c;
      EXPECT_LT(ratio, 1.25f) << "d " << d << " channel " << c;
    }
  }
}
