#pragma once
// A bounding volume hierarchy over a mesh's triangles for the nearest-hit rays of the thickness
// bake: binary, split along the longest axis of the centroids' box where the binned surface
// area heuristic puts it (the median where that fails), leaves of at most four triangles; Moller-Trumbore ray/triangle tests (both sides count: a ray cast inward leaves
// through a back face).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "marble/mesh/mesh.h"

namespace marble {

// The nearest hit of a ray: its distance (negative: none), the triangle (the mesh's index) and the
// hit's barycentric weights of the triangle's second and third corners.
struct RayHit {
  float t = -1.0f;
  uint32_t triangle = 0;
  float u = 0.0f, v = 0.0f;
};

class RayBvh {
 public:
  explicit RayBvh(const Mesh& mesh);
  // Distance to the nearest triangle along origin + t * dir for t in (0, maxT), or a negative
  // value when there is none. `dir` need not be unit length (t is in its units).
  float nearestHit(glm::vec3 origin, glm::vec3 dir, float maxT) const { return nearest(origin, dir, maxT).t; }
  // The same ray's nearest hit with its triangle (the further bounces' patches, further_radiosity.h).
  RayHit nearest(glm::vec3 origin, glm::vec3 dir, float maxT) const;

 private:
  struct Node {
    glm::vec3 lo, hi;
    uint32_t first;  // leaf: first triangle; inner: index of the left child
    uint32_t count;  // triangles in a leaf; 0 for an inner node
    uint32_t right;  // inner: index of the right child
  };
  uint32_t build(uint32_t begin, uint32_t end, std::vector<glm::vec3>& centroids);
  uint32_t splitPoint(uint32_t begin, uint32_t end, int axis, float lo, float extent, const std::vector<glm::vec3>& centroids) const;
  std::vector<Node> nodes_;
  std::vector<glm::vec3> corners_;  // three per triangle, in the order of the leaves
  std::vector<uint32_t> triangles_;  // the mesh's index of each, in the same order
};

}  // namespace marble
