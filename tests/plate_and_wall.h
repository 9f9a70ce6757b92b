// A plate with a wall standing on it, and where the wall's shadow ends on the plate: the scene of
// the GL tests that find a shadow's edge (GrazingShadow, BlurAlongSurface).
#pragma once

#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "box_mesh.h"
#include "marble/mesh/vertex_normals.h"
#include "marble/scene/scene.h"
#include "principled_stone.h"

namespace marble::test {

// The plate's top at y = 0 with the wall (0.1 thick, `height` tall, its +x face at x = wallX) on
// it; both span [-1, 1] in x and z and the whole is centred in y (the plate is `height` thick), so
// the renderer's normalization (bounding box centred, largest extent 2) leaves it where it is.
inline Mesh plateAndWall(float wallX, float height) {
  Mesh m;
  addBox(m, {-1.0f, -height, -1.0f}, {1.0f, 0.0f, 1.0f});
  addBox(m, {wallX - 0.1f, 0.0f, -1.0f}, {wallX, height, 1.0f});
  computeVertexNormals(m, 60.0f);  // flat faces
  return m;
}

// One such scene lit from -x at `elevationDeg`: its mesh, and where the wall's shadow ends.
struct PlateAndWall {
  float wallX, height, elevationDeg;
  Mesh mesh() const { return plateAndWall(wallX, height); }
  float shadowEnd() const { return wallX + height / std::tan(glm::radians(elevationDeg)); }
};

// A plate whose top is at y = 0 seen from 3 units straight above x (`fovDeg` wide, 128²), lit by a
// directional light from -x at `elevationDeg`, the stone, in `marble` mode without the
// environment: the scene of the tests that find where a grazing light's shadow ends
// (GrazingShadow, ReceiverPlaneShadow).
inline Scene grazingLightSeenFromAbove(const std::string& mesh, float x, float elevationDeg, float fovDeg) {
  Scene s;
  s.mesh = mesh;
  s.render.width = s.render.height = 128;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  s.camera.position = {x, 3.0f, 0.0f};
  s.camera.target = {x, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_deg = fovDeg;
  s.light.type = LightType::Directional;
  const float e = glm::radians(elevationDeg);
  s.light.position = {-std::cos(e), std::sin(e), 0.0f};  // toward the light
  s.light.intensity = 1.0f;
  s.material = principledStone();
  return s;
}

}  // namespace marble::test
