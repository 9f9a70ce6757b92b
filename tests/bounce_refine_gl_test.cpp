// The `marble` bounce's refined grid (BouncePass, shaders/bounce_refine_mark.comp.glsl): the first
// bounce is gathered again at half the coarse grid's spacing only where the coarse samples around a
// texel do not continue its surface. In a fold (a wall standing on a plate, seen at 45 degrees) the
// crease and the silhouettes have such texels; a plate that fills the frame, seen from above, has
// none, so there the lighting pass reads the coarse grid alone, exactly as before the refinement.
// Negative control (by hand, session 17): BOUNCE_REFINE_BELOW 0 refines nothing and the fold's
// test fails; the test of the open plate fails with BOUNCE_REFINE_BELOW 1.01 (every texel refined).
#include <gtest/gtest.h>

#include <iostream>

#include "box_mesh.h"
#include "gl_support.h"
#include "principled_stone.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;

namespace {

Mesh fold() {
  Mesh m;
  addBox(m, {-0.1f, -0.6f, -1.0f}, {0.1f, 1.0f, 1.0f});  // the wall
  addBox(m, {0.1f, -0.8f, -1.0f}, {1.0f, -0.6f, 1.0f});  // the plate
  computeVertexNormals(m, 60.0f);                         // flat faces
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

TEST(BounceRefine, TheFoldsCreaseAndSilhouettesAreRefined) {
  // 128² at the blur's half: the coarse grid's texel is 8 pixels, the refined grid's 4 (32² texels).
  const int n = refinedTexels(fold(), scene({2.1f, 1.4f, 0.0f}, {0.4f, -0.3f, 0.0f}));
  std::cout << "[          ] fold: " << n << " refined texels of 1024\n";
  EXPECT_GT(n, 10);
  EXPECT_LT(n, 1024 / 3);  // the crease and the edges, not the faces
}

TEST(BounceRefine, AnOpenPlateFillingTheFrameIsNotRefined) {
  // The plate's top, seen from 0.6 above at a slant: its edges are out of the frame.
  EXPECT_EQ(refinedTexels(plate(), scene({0.0f, 0.7f, 0.25f}, {0.0f, 0.1f, 0.0f})), 0);
}
