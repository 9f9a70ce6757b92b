#pragma once
// Scan conversion of triangles in texture space, shared by the bake and the overlap check.
// Sample points are the centres of a res x res grid over [0,1]^2 (row 0 at v = 1, the image's top
// row, as PNG stores it); a sample on an edge shared by two triangles belongs to exactly one of
// them (top-left rule), so a seamless layout covers every sample at most once.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "marble/mesh/mesh.h"

namespace marble {

// Calls visit(x, y, barycentric) for every sample inside the triangle (uv in [0,1]^2 units); the
// sample of cell (x, y) lies at (x, y) + offset in cell units ({0.5, 0.5}: the centre; other
// offsets give the sub-samples of a supersampled bake).
void rasterizeUvTriangle(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, int res,
                         const std::function<void(int x, int y, glm::vec3 bary)>& visit,
                         glm::vec2 offset = {0.5f, 0.5f});

struct UvOverlap {
  uint64_t coveredSamples = 0;  // samples inside at least one triangle
  uint64_t overlapSamples = 0;  // samples inside two or more
  uint64_t outsideTriangles = 0;  // triangles with a texcoord outside [0,1]
};
// Counts, on a res x res grid, samples covered by more than one triangle of the mesh.
UvOverlap measureUvOverlap(const Mesh& mesh, int res);

}  // namespace marble
