#pragma once
// A Mesh uploaded to the GPU once: interleaved position+normal and a 32-bit index buffer. Where GL
// rasterizes in software, the positions and indices stay on the CPU too, for the mesh passes' cull
// before GL (screen_cull.h, gl/software_rasterizer.h).
#include <cstdint>

#include "marble/gl/handles.h"
#include "marble/mesh/closed_surface.h"
#include "marble/mesh/mesh.h"
#include "marble/render/screen_cull.h"

namespace marble {

class GpuMesh {
public:
  GpuMesh() = default;
  explicit GpuMesh(const Mesh& mesh);
  void draw() const;
  // Whether the cull before GL is prepared (a software rasterizer, a mesh with triangles).
  bool cullsOnCpu() const { return !screenCull_.indices.empty(); }
  // Where cullsOnCpu, a second index buffer of the mesh's size, for a subset of its triangles
  // (screen_cull.h): mapSubset gives it to be written (write only, its old contents invalidated;
  // nullptr where there is none), unmapSubset hands it back, drawSubset draws its first `count`
  // indices (at most the mesh's own count).
  uint32_t* mapSubset() const;
  void unmapSubset() const;
  void drawSubset(size_t count) const;
  const ScreenCullMesh& screenCullMesh() const { return screenCull_; }
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
  gl::Buffer vertices_, indices_, subsetIndices_;
  ScreenCullMesh screenCull_;
  gl::VertexArray vao_;
  GLsizei indexCount_ = 0;
  size_t bytes_ = 0;
  glm::vec3 boundsMin_{0.0f}, boundsMax_{0.0f};
  bool woundInward_ = false;
  SurfaceWinding winding_ = SurfaceWinding::Open;
};

}  // namespace marble
