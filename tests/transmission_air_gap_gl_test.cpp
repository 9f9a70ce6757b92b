// The `marble` mode's transmission through two pieces of stone with air between them
// (shaders/transmission_air_gap.glsl; docs/quality.md, "Twenty-ninth session: ... the air between
// two parts"): a plate 1.8 mm thick toward the light, 4.8 mm of air, a plate 9.6 mm thick, lit from
// straight behind and seen head-on from the other side, so the camera sees the far plate's far face.
// The light's map finds the near plate's entry 16.2 mm before that face and, read as one chord,
// counts the air as stone: the two plates glowed exactly as one 16.2 mm plate. The references'
// Cycles carries nothing through the second piece (its subsurface weight is 0 after the diffuse
// bounce that crosses the air): rendered with tools/cycles_reference.py at 128 samples, the two
// plates are 0 in every pixel, the one plate 0.024 / 0.0061 / 0.0012. The gather must count no
// light from entries whose way to the exit crosses air behind a first part.
#include <gtest/gtest.h>

#include <initializer_list>
#include <iostream>
#include <utility>

#include "gl_support.h"
#include "image_probe.h"
#include "principled_stone.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 128;
constexpr float kMmPerUnit = 20.0f;  // the plates 40 mm square
constexpr float kNear0 = -0.405f, kNear1 = -0.315f;  // scene units along the light: 1.8 mm of stone,
constexpr float kFar0 = -0.075f, kFar1 = 0.405f;     // 4.8 mm of air, 9.6 mm of stone

// Boxes 2 units square in x and y, each spanning [z0, z1]; flat faces (the crease angle splits
// every edge).
Mesh plates(std::initializer_list<std::pair<float, float>> spans) {
  Mesh m;
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& [z0, z1] : spans) {
    const auto base = static_cast<uint32_t>(m.positions.size());
    for (int i = 0; i < 8; ++i) m.positions.push_back({(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? z1 : z0});
    // Faces as quads of corner indices, counter-clockwise seen from outside.
    for (const auto& q : quads)
      for (uint32_t v : {q[0], q[1], q[2], q[0], q[2], q[3]}) m.indices.push_back(base + v);
  }
  computeVertexNormals(m, 60.0f);
  return m;
}

// The glow at the middle of the far face (the light through the stone: nothing else lights the face
// turned from a light straight behind).
glm::vec3 glowThrough(Renderer& renderer, const Mesh& mesh) {
  const Scene s = test::backLitScene("test:plates", kMmPerUnit, kSize);
  renderer.setMesh(mesh);
  renderImage(renderer, s);
  return linearRgbAround(renderer.readHdr(), s, {0, 0, kFar1});
}

// Cycles' two plates are 0; the bound leaves room for the blur's and the rings' edges.
constexpr float kMostOfOnePlate = 0.05f;

}  // namespace

TEST(TransmissionAirGap, NoLightThroughASecondPieceBehindAir) {
  glContext();
  Renderer renderer;
  const glm::vec3 two = glowThrough(renderer, plates({{kNear0, kNear1}, {kFar0, kFar1}}));
  const glm::vec3 one = glowThrough(renderer, plates({{kNear0, kFar1}}));
  std::cout << "[          ] two plates " << two.r << " " << two.g << " " << two.b << ", one plate " << one.r << " " << one.g
            << " " << one.b << ", two / one " << two.r / one.r << " " << two.g / one.g << " " << two.b / one.b << "\n";
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(one[c], 0.0f) << "channel " << c << ": one plate of the same chord must let light through";
    EXPECT_LT(two[c], kMostOfOnePlate * one[c]) << "channel " << c << ": the air between the plates counted as stone";
  }
}
