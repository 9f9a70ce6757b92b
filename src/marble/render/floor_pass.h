#pragma once
// The floor of a frame (issue 8, `--mode floor`): the mesh drawn once, flat-shaded, straight
// into the target. What a changing view cannot cost less than.
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
  gl::Program program_;
  PassTimer timer_;
};

}  // namespace marble
