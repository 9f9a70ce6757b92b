#pragma once
// The floor of a frame (issue 8, `--mode floor`): the mesh drawn once, flat-shaded, with a
// depth test, into the pass's own colour and depth buffers, then copied to the target (which
// need not have a depth buffer). What a changing view cannot cost less than.
#include "marble/gl/program.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/pass_timer.h"
#include "marble/render/view_setup.h"

namespace marble {

class FloorPass {
public:
  explicit FloorPass(const ShaderLibrary& shaders);
  void run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera, const glm::vec3& lightPos,
           const glm::vec3& color, const glm::vec3& background, GLuint targetFbo, int width, int height);
  PassTimer& timer() { return timer_; }

private:
  void resize(int width, int height);
  gl::Program program_;
  gl::Texture color_, depth_;
  gl::Framebuffer fbo_;
  int width_ = 0, height_ = 0;
  PassTimer timer_;
};

}  // namespace marble
