#pragma once
// Pass 3: full screen. Reads the G-buffer and the light's distance map; writes the render
// mode's picture into the target framebuffer (the window's, or an offscreen one).
#include "marble/gl/program.h"
#include "marble/render/pass_timer.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

struct LightingInputs {
  GLuint albedo, normal, depth, lightDistance;
};

class LightingPass {
public:
  explicit LightingPass(const ShaderLibrary& shaders);
  void run(const LightingInputs& in, const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
           const Material& material, const RenderSettings& settings, GLuint targetFbo, int width, int height);
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_;
  gl::VertexArray emptyVao_;  // core profile needs a VAO bound even for attribute-less draws
  PassTimer timer_;
};

}  // namespace marble
