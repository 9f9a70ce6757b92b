// An axis-aligned box appended to a mesh: the building block of the GL tests' small scenes
// (slabs, walls, plates). Its normals are left to the caller (computeVertexNormals with a crease
// angle below 90 degrees gives flat faces).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "marble/mesh/mesh.h"
#include "marble/mesh/vertex_normals.h"

namespace marble::test {

inline void addBox(Mesh& m, glm::vec3 lo, glm::vec3 hi) {
  const auto base = static_cast<uint32_t>(m.positions.size());
  for (int i = 0; i < 8; ++i)
    m.positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  // Quads wound counter-clockwise seen from outside: -z, +z, -y, +y, -x, +x.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
    for (int t : {0, 1, 2, 0, 2, 3}) m.indices.push_back(base + static_cast<uint32_t>(q[t]));
}

// The bounce tests' thin plate (5 mm at 100 mm per unit, its top at y = kPlateTop, x from kWall to
// 1) with, optionally, a wall standing on its end (x in [-kWall, kWall], up to y = 1); z in
// [-1, 1]. Flat faces. In a namespace of its own: other tests name their own kWall.
namespace thin_plate {
constexpr float kWall = 0.1f, kPlateTop = -0.6f, kPlate = 0.05f;

inline Mesh plateWithWall(bool withWall) {
  Mesh m;
  if (withWall) addBox(m, {-kWall, kPlateTop, -1.0f}, {kWall, 1.0f, 1.0f});
  addBox(m, {kWall, kPlateTop - kPlate, -1.0f}, {1.0f, kPlateTop, 1.0f});
  computeVertexNormals(m, 60.0f);  // flat faces
  return m;
}
}  // namespace thin_plate

}  // namespace marble::test
