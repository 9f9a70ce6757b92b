#include "marble/render/blur_depth_pass.h"

#include "marble/gl/checked_calls.h"
#include "marble/render/shader_constants.h"

namespace marble {

BlurDepthPass::BlurDepthPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "blur_depth.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {}

bool BlurDepthPass::resize(int width, int height, int scale, GLuint gBufferDepth) {
  const int w = (width + scale - 1) / scale, h = (height + scale - 1) / scale;  // rounded up, as the blur's
  gBufferDepth_ = gl::Borrowed(gBufferDepth);
  if (w == width_ && h == height_ && scale == scale_) return false;
  width_ = w;
  height_ = h;
  scale_ = scale;
  if (scale == 1) {
    depth_ = {};
    fbo_ = {};
    return true;
  }
  depth_ = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, w, h, GL_NEAREST);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
  return true;
}

void BlurDepthPass::run(const ScreenRect& rect) {
  if (scale_ == 1) return;
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::setDepthCopyScreenPassState();
  const float one = 1.0f;
  gl::clearFramebuffer(fbo_.id(), GL_DEPTH, 0, &one);
  scissorTo(scaledDown(rect, scale_));
  glBindTextureUnit(shader::UNIT_SCREEN_INPUT, gBufferDepth_.id());
  program_.set("u_scale", scale_);
  gl::drawFullscreenTriangle(program_.id(), emptyVao_.id());
  scissorOff();
  timer_.end();
}

}  // namespace marble
