// A flat box for the transmission tests: 2 halfWidth square, 2 halfThickness thick, hard-edged
// (the crease splits its faces), so its faces are the flat entry and exit a slab test needs.
#pragma once

#include <cstdint>

#include "marble/mesh/mesh.h"
#include "marble/mesh/vertex_normals.h"

namespace marble::test {

inline Mesh slabMesh(float halfWidth, float halfThickness) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.positions.push_back({(i & 1) ? halfWidth : -halfWidth, (i & 2) ? halfWidth : -halfWidth,
                           (i & 4) ? halfThickness : -halfThickness});
  // Quads wound counter-clockwise seen from outside: -z, +z, -y, +y, -x, +x.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
    for (int t : {0, 1, 2, 0, 2, 3}) m.indices.push_back(static_cast<uint32_t>(q[t]));
  computeVertexNormals(m, 60.0f);
  return m;
}

}  // namespace marble::test
