// A plate with a wall standing on it, and where the wall's shadow ends on the plate: the scene of
// the GL tests that find a shadow's edge (GrazingShadow, BlurAlongSurface).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "box_mesh.h"
#include "marble/mesh/vertex_normals.h"

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

}  // namespace marble::test
