#include "marble/render/bounce_grid_depth.h"

#include "marble/gl/checked_calls.h"

namespace marble {

void BounceGridDepth::resize(int width, int height) {
  width_ = width;
  height_ = height;
  depth_ = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
}

void BounceGridDepth::fill(const gl::Program& program, GLuint emptyVao, int scale, int gridWidth, int gridHeight,
                           const ScreenRect& cells) const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, gridWidth, gridHeight);
  gl::setDepthCopyScreenPassState();
  const float far = 1.0f;
  gl::clearFramebuffer(fbo_.id(), GL_DEPTH, 0, &far);
  scissorTo(cells);
  program.set("u_scale", scale);
  gl::drawFullscreenTriangle(program.id(), emptyVao);
  scissorOff();
}

}  // namespace marble
