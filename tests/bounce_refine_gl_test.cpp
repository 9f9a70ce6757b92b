// The `marble` bounce's refined grid (BouncePass, shaders/bounce_refine_mark.comp.glsl): the first
// bounce is gathered again at half the coarse grid's spacing only where the coarse samples around a
// texel do not continue its surface (their bilateral weights sum below 0.4). A rod a few pixels wide,
// tilted in the picture, falls between the coarse grid's samples along much of its length: there
// its refined-grid texels have no coarse sample on the rod and are refined. A plate that fills the
// frame, seen from above, has none, so there the lighting pass reads the coarse grid alone, exactly
// as before the refinement. (A fold of flat faces refines nothing at 0.4: on a crease or a straight
// silhouette half the bilinear weight stays on a sample of the texel's own face.)
// Negative controls (by hand, session 17): BOUNCE_REFINE_BELOW -1 refines nothing and the rod's test
// fails; 2 refines every texel tested and the plate's test fails.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "box_mesh.h"
#include "gl_support.h"
#include "principled_stone.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;

namespace {

// A rod 0.05 thick (~3 pixels at 128²) and 2 long, turned 30 degrees about the view axis.
Mesh tiltedRod() {
  Mesh m;
  addBox(m, {-0.025f, -1.0f, -0.025f}, {0.025f, 1.0f, 0.025f});
  const float c = std::cos(glm::radians(30.0f)), s = std::sin(glm::radians(30.0f));
  for (glm::vec3& p : m.positions) p = {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
  computeVertexNormals(m, 60.0f);
  return m;
}

// The rod above a lit plate, which bounces light onto the rod's faces the camera sees.
Mesh rodOverPlate() {
  Mesh m = tiltedRod();
  addBox(m, {-1.2f, -1.1f, -1.2f}, {1.2f, -0.95f, 1.2f});
  computeVertexNormals(m, 60.0f);
  return m;
}

Mesh plate() {
  Mesh m;
  addBox(m, {-1.0f, -0.1f, -1.0f}, {1.0f, 0.1f, 1.0f});
  computeVertexNormals(m, 60.0f);
  return m;
}

Scene scene(glm::vec3 camera, glm::vec3 target) {
  Scene s;
  s.mesh = "test:refine";
  s.mm_per_unit = 1000.0f;
  s.render.width = s.render.height = 128;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  s.camera.position = camera;
  s.camera.target = target;
  s.camera.fov_y_deg = 40;
  s.light.type = LightType::Directional;
  s.light.position = {0.3f, 1.0f, 0.2f};
  s.light.intensity = 1.0f;
  s.material = test::principledStone(glm::vec3(0.8f));
  return s;
}

int refinedTexels(Mesh mesh, const Scene& s) {
  glContext();
  Renderer r;
  r.setMesh(std::move(mesh));
  renderImage(r, s);
  return r.bounceRefinedTexels();
}

}  // namespace

TEST(BounceRefine, ARodBetweenTheCoarseSamplesIsRefined) {
  // 128² at the blur's half: the coarse grid's texel is 8 pixels, the refined grid's 4 (32² texels).
  const int n = refinedTexels(tiltedRod(), scene({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}));
  std::cout << "[          ] rod: " << n << " refined texels of 1024\n";
  EXPECT_GT(n, 5);
  EXPECT_LT(n, 1024 / 8);  // along the rod, not the frame
}

TEST(BounceRefine, AnOpenPlateFillingTheFrameIsNotRefined) {
  // The plate's top, seen from 0.6 above at a slant: its edges are out of the frame.
  EXPECT_EQ(refinedTexels(plate(), scene({0.0f, 0.7f, 0.25f}, {0.0f, 0.1f, 0.0f})), 0);
}

// A base colour change re-runs the bounce pass without its gathers (the merge applies the colour):
// the refined texels are marked again and merged again from their stored first bounce, and the
// frame equals a fresh render of the changed scene exactly. Negative control (by hand): with
// mergeRefined() left out of the merge-only run the refined texels keep the old colour's merge and
// the frames differ.
TEST(BounceRefine, ABaseColourChangeRemergesTheRefinedTexelsAsAFreshRenderDoes) {
  glContext();
  Scene s = scene({0.0f, 0.6f, 3.0f}, {0.0f, -0.4f, 0.0f});
  Renderer cached, fresh;
  cached.setMesh(rodOverPlate());
  renderImage(cached, s);
  ASSERT_GT(cached.bounceRefinedTexels(), 0);
  s.material.base_color = glm::vec3(0.3f, 0.6f, 0.2f);
  renderImage(cached, s);
  const PassTimes t = cached.passTimes(true);
  EXPECT_FALSE(t.ran[Pass::Geometry]);
  EXPECT_TRUE(t.ran[Pass::Bounce]) << "its merge applies the base colour";
  const ImageRGBF a = cached.readHdr();
  fresh.setMesh(rodOverPlate());
  renderImage(fresh, s);
  const ImageRGBF b = fresh.readHdr();
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t differ = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(differ, 0u);
}

