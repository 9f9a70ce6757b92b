#include "marble/render/bounce_pass.h"

#include "marble/render/frame_uniforms.h"
#include "marble/render/shader_constants.h"

namespace marble {

BouncePass::BouncePass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "bounce_gather.frag.glsl"}}),
      furtherProgram_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "bounce_further.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {}

void BouncePass::resize(int width, int height, int lightingScale) {
  const int scale = bounceScale(lightingScale);
  const int w = (width + scale - 1) / scale, h = (height + scale - 1) / scale;  // rounded up: every pixel has one
  if (w == width_ && h == height_ && scale == scale_ && fbo_) return;
  width_ = w;
  height_ = h;
  scale_ = scale;
  // Nearest: the upsample reads texels by index and weighs them itself.
  bounce_ = gl::makeTexture2D(GL_RGBA16F, w, h, GL_NEAREST);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, bounce_.id(), 0);
  further_ = gl::makeTexture2D(GL_RGBA16F, w, h, GL_NEAREST);
  furtherFbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(furtherFbo_.id(), GL_COLOR_ATTACHMENT0, further_.id(), 0);
}

void BouncePass::run(const BounceInputs& in, const CameraMatrices& camera, const LightMatrices& lightM,
                     const Light& light, float lightTexelWorld, const ScreenRect& rect) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::setScreenPassState();
  // Outside the rectangle there is no surface: alpha -1, which the upsample leaves out (alpha >= 0
  // is a surface's mirrored bounce, bounce_gather.frag.glsl).
  const float none[4] = {0, 0, 0, -1};
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, none);
  scissorTo(scaledDown(rect, scale_));
  glBindTextureUnit(shader::UNIT_LIGHTING_NORMAL, in.normal);
  glBindTextureUnit(shader::UNIT_LIGHTING_DEPTH, in.depth);
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE_POSITION, in.bouncePosition);
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE_NORMAL, in.bounceNormal);
  setFrameUniforms(program_, camera, lightM, light, lightTexelWorld);
  program_.set("u_scale", scale_);
  gl::drawFullscreenTriangle(program_.id(), emptyVao_.id());
  // The further bounces, from the first bounce just drawn (outside the rectangle: none).
  glBindFramebuffer(GL_FRAMEBUFFER, furtherFbo_.id());
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(furtherFbo_.id(), GL_COLOR, 0, zero);
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE, bounce_.id());
  setFrameUniforms(furtherProgram_, camera, lightM, light, lightTexelWorld);
  furtherProgram_.set("u_scale", scale_);
  gl::drawFullscreenTriangle(furtherProgram_.id(), emptyVao_.id());
  scissorOff();
  timer_.end();
}

}  // namespace marble
