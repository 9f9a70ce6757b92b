// A flat box for the transmission tests: 2 halfWidth square, 2 halfThickness thick, hard-edged
// (the crease splits its faces), so its faces are the flat entry and exit a slab test needs.
#pragma once

#include "box_mesh.h"
#include "marble/mesh/vertex_normals.h"

namespace marble::test {

inline Mesh slabMesh(float halfWidth, float halfThickness) {
  Mesh m;
  addBox(m, {-halfWidth, -halfWidth, -halfThickness}, {halfWidth, halfWidth, halfThickness});
  computeVertexNormals(m, 60.0f);
  return m;
}

}  // namespace marble::test
