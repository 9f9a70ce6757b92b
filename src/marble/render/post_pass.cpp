#include "marble/render/post_pass.h"

#include <cmath>

namespace marble {

PostPass::PostPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "post.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {}

void PostPass::run(GLuint hdrTexture, GLuint depthTexture, const RenderSettings& settings, GLuint targetFbo, int width,
                   int height) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glViewport(0, 0, width, height);
  gl::setScreenPassState();
  const GLuint textures[] = {hdrTexture, depthTexture};
  glBindTextures(0, 2, textures);
  program_.set("u_tone_map", settings.mode == RenderMode::Marble ? 1 : 0);
  program_.set("u_exposure_scale", std::exp2(settings.exposure));
  program_.set("u_paint_background", settings.mode == RenderMode::LightDepth ? 0 : 1);
  program_.set("u_background", settings.background);
  glUseProgram(program_.id());
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  timer_.end();
}

}  // namespace marble
