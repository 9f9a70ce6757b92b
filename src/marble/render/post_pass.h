#pragma once
// Last pass: the lighting pass's linear HDR image to the target framebuffer. The `marble`
// mode is exposed, tone mapped (Khronos PBR Neutral) and sRGB-encoded; the paper's modes and
// the buffer views pass through unchanged.
#include "marble/gl/program.h"
#include "marble/render/pass_timer.h"
#include "marble/scene/scene.h"

namespace marble {

class PostPass {
public:
  explicit PostPass(const ShaderLibrary& shaders);
  void run(GLuint hdrTexture, GLuint depthTexture, const RenderSettings& settings, GLuint targetFbo, int width, int height);
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_;
  gl::VertexArray emptyVao_;
  PassTimer timer_;
};

}  // namespace marble
