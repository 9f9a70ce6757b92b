#pragma once
// A Mesh uploaded to the GPU once: interleaved position+normal and a 32-bit index buffer.
#include "marble/gl/handles.h"
#include "marble/mesh/closed_surface.h"
#include "marble/mesh/mesh.h"

namespace marble {

class GpuMesh {
public:
  GpuMesh() = default;
  explicit GpuMesh(const Mesh& mesh);
  void draw() const;
  size_t triangleCount() const { return indexCount_ / 3; }
  size_t bytes() const { return bytes_; }
  bool empty() const { return indexCount_ == 0; }
  // Object-space bounding box of the positions (for the screen passes' scissor rectangle).
  const glm::vec3& boundsMin() const { return boundsMin_; }
  const glm::vec3& boundsMax() const { return boundsMax_; }
  // Whether the triangles enclose a negative signed volume (wound clockwise seen from outside, so
  // their vertex normals point in): the light's layers take a surface's outside from it. Defined
  // for open meshes too (the teapot), where winding() says Open.
  bool woundInward() const { return woundInward_; }
  // Whether the triangles bound a solid, and their sense (for the camera's face culling).
  SurfaceWinding winding() const { return winding_; }

private:
  gl::Buffer vertices_, indices_;
  gl::VertexArray vao_;
  GLsizei indexCount_ = 0;
  size_t bytes_ = 0;
  glm::vec3 boundsMin_{0.0f}, boundsMax_{0.0f};
  bool woundInward_ = false;
  SurfaceWinding winding_ = SurfaceWinding::Open;
};

}  // namespace marble
