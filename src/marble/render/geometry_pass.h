#pragma once
// Pass 2: the mesh seen from the camera into a lean G-buffer:
//   normals RGBA16_SNORM   8 bytes  (octahedral, world space) .xy: the normal; .zw: the normal
//                                   the post pass's reflection terms read (marble mode: bent by
//                                   Cycles' valid-reflection rule; otherwise the same as .xy)
//   depth   DEPTH32F       4 bytes  (position is reconstructed from it)
// One target for both normals: two RG16 targets cost llvmpipe a second clear and store per
// fragment. The albedo (RGBA8, 4 bytes) is added by the AlbedoPass: 12 bytes per pixel plus depth.
#include "marble/gl/program.h"
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
  void run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera, bool validReflection);
  // Both normals (.xy the normal, .zw the reflection terms' normal; shaders/geometry.frag.glsl).
  GLuint normalTexture() const { return normals_.id(); }
  GLuint depthTexture() const { return depth_.id(); }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 12; }
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_;
  gl::Texture normals_, depth_;
  gl::Framebuffer fbo_;
  int width_ = 0, height_ = 0;
  PassTimer timer_;
};

}  // namespace marble
