#pragma once
// Pass 1: the mesh seen from the light into a map of world-space distances (R32F) with its
// own depth buffer. Read by the lighting pass for thickness (and later shadows).
#include "marble/gl/program.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/pass_timer.h"
#include "marble/render/view_setup.h"

namespace marble {

class LightDepthPass {
public:
  LightDepthPass(const ShaderLibrary& shaders, int size = 1024);
  void run(const GpuMesh& mesh, const glm::mat4& model, const LightMatrices& light);
  GLuint distanceTexture() const { return distance_.id(); }
  GLuint depthTexture() const { return depth_.id(); }  // compare mode on, for sampler2DShadow
  int size() const { return size_; }
  size_t bytes() const { return static_cast<size_t>(size_) * size_ * 8; }
  PassTimer& timer() { return timer_; }

private:
  int size_;
  gl::Program program_;
  gl::Texture distance_, depth_;
  gl::Framebuffer fbo_;
  PassTimer timer_;
};

}  // namespace marble
