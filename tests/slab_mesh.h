// Meshes for the transmission tests. slabMesh: a flat box, 2 halfWidth square, 2 halfThickness
// thick, hard-edged (the crease splits its faces), so its faces are the flat entry and exit a slab
// test needs; shellMesh: a curved plate of even thickness.
#pragma once

#include <cmath>
#include <cstdint>

#include "box_mesh.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/vertex_normals.h"

namespace marble::test {

inline Mesh slabMesh(float halfWidth, float halfThickness) {
  Mesh m;
  addBox(m, {-halfWidth, -halfWidth, -halfThickness}, {halfWidth, halfWidth, halfThickness});
  computeVertexNormals(m, 60.0f);
  return m;
}

// A curved plate of even thickness (a shell): the part of a cylinder wall round the y axis between
// radii outerRadius - thickness and outerRadius, halfAngle either side of +z, y within +-halfLength,
// closed by hard-edged caps. Its outer face's middle is at (0, 0, frontZ), facing +z; the entry
// (inner) face lies parallel to it, `thickness` behind, everywhere. Smooth faces (segments flat
// pieces each) so the stored entry cosine changes across the plate as on a curved thin part (an
// ear, a leaf).
inline Mesh shellMesh(float outerRadius, float thickness, float halfAngle, float halfLength, float frontZ,
                      int segments) {
  Mesh m;
  const glm::vec3 centre(0.0f, 0.0f, frontZ - outerRadius);
  auto at = [&](float radius, int i, float y) {
    const float phi = -halfAngle + 2.0f * halfAngle * static_cast<float>(i) / static_cast<float>(segments);
    return centre + glm::vec3(radius * std::sin(phi), y, radius * std::cos(phi));
  };
  // A quad a b c d with its outward direction: wound so that its normal points along `out`.
  auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 out) {
    const uint32_t base = static_cast<uint32_t>(m.positions.size());
    for (const glm::vec3& p : {a, b, c, d}) m.positions.push_back(p);
    const bool flip = glm::dot(glm::cross(b - a, c - a), out) < 0.0f;
    const uint32_t order[6] = {0, 1, 2, 0, 2, 3};
    for (int t = 0; t < 6; ++t) m.indices.push_back(base + (flip ? order[5 - t] : order[t]));
  };
  const float inner = outerRadius - thickness;
  for (int i = 0; i < segments; ++i) {
    const glm::vec3 mid = at(1.0f, i, 0.0f) + at(1.0f, i + 1, 0.0f) - 2.0f * centre;  // radial, outward
    quad(at(outerRadius, i, -halfLength), at(outerRadius, i + 1, -halfLength), at(outerRadius, i + 1, halfLength),
         at(outerRadius, i, halfLength), mid);
    quad(at(inner, i, -halfLength), at(inner, i + 1, -halfLength), at(inner, i + 1, halfLength), at(inner, i, halfLength),
         -mid);
    for (float y : {-halfLength, halfLength})
      quad(at(inner, i, y), at(inner, i + 1, y), at(outerRadius, i + 1, y), at(outerRadius, i, y), {0.0f, y, 0.0f});
  }
  for (int i : {0, segments}) {
    const glm::vec3 side = at(1.0f, i, 0.0f) - centre;
    const glm::vec3 out = glm::cross(side, glm::vec3(0.0f, 1.0f, 0.0f)) * (i == 0 ? 1.0f : -1.0f);
    quad(at(inner, i, -halfLength), at(outerRadius, i, -halfLength), at(outerRadius, i, halfLength), at(inner, i, halfLength),
         out);
  }
  computeVertexNormals(m, 60.0f);
  return m;
}

}  // namespace marble::test
