#pragma once
// Pass 2: the mesh seen from the camera into a lean G-buffer:
//   normal  RG16_SNORM     4 bytes  (octahedral, world space)
//   specular normal RGBA16_SNORM 8 bytes (marble mode: xy the normal bent by Cycles' valid-reflection
//                                   rule, read by the post pass's reflection terms; zw the
//                                   interpolated normal, for the highlight's footprint steps)
//   depth   DEPTH32F       4 bytes  (position is reconstructed from it)
// The albedo (RGBA8, 4 bytes) is added by the AlbedoPass.
#include "marble/gl/program.h"
#include "marble/render/face_culling.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/pass_timer.h"
#include "marble/render/view_setup.h"

namespace marble {

class GeometryPass {
public:
  explicit GeometryPass(const ShaderLibrary& shaders);
  void resize(int width, int height);
  // validReflection: also store the normal bent by Cycles' valid-reflection rule
  // (shaders/valid_reflection.glsl), for `marble` mode, whose Principled reference applies it.
  // The faces no camera ray meets first are not drawn (render/face_culling.h) unless switched off.
  void run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera, bool validReflection);
  // For tests: whether hidden faces are culled (on by default).
  void setCullsHiddenFaces(bool on) { cullsHiddenFaces_ = on; }
  // For tests: whether the triangles GL's culling would discard are first dropped on the CPU
  // (render/screen_cull.h; on by default, only where hidden faces are culled and GL rasterizes in
  // software: GpuMesh::cullsOnCpu).
  void setCullsOnCpu(bool on) { cullsOnCpu_ = on; }
  GLuint normalTexture() const { return normal_.id(); }
  // The normal for the reflection terms: the bent one where the last run stored it, else the normal.
  GLuint specularNormalTexture() const { return validReflection_ ? specularNormal_.id() : normal_.id(); }
  GLuint depthTexture() const { return depth_.id(); }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 16; }
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_;
  gl::Texture normal_, specularNormal_, depth_;
  gl::Framebuffer fbo_;
  int width_ = 0, height_ = 0;
  bool validReflection_ = false;
  bool drawBuffersSet_ = false;  // fbo_'s draw buffers match validReflection_
  bool cullsHiddenFaces_ = true;
  bool cullsOnCpu_ = true;
  HiddenFaceDraw hiddenFaceDraw_;
  PassTimer timer_;
};

}  // namespace marble
