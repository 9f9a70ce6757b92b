#include "marble/render/fxaa_pass.h"

namespace marble {

namespace {
// Steps of the edge search each way (shaders/fxaa.frag.glsl, searchStep): 1, 1, 1, 1, 1.5, 2, 2,
// 2, 4, 8 texels, 23.5 in all, about the reach of Lottes' default quality preset.
constexpr int kSearchSteps = 10;
}  // namespace

FxaaPass::FxaaPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "fxaa.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {
  program_.set("u_search_steps", kSearchSteps);
}

void FxaaPass::run(GLuint displayImage, GLuint targetFbo, int width, int height, const ScreenRect& rect,
                   const glm::vec3& background) {
  timer_.begin();
  gl::setScreenPassState();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glViewport(0, 0, width, height);
  // llvmpipe runs the whole edge search for every pixel it shades (both sides of every branch),
  // so the flat background around the rectangle is cleared instead of filtered.
  if (rect.x > 0 || rect.y > 0 || rect.width < width || rect.height < height) {
    const glm::vec4 clear(background, 1.0f);
    scissorTo({0, 0, width, height});  // the target may be larger than the frame
    glClearBufferfv(GL_COLOR, 0, &clear.x);
  }
  scissorTo(rect);
  glBindTextureUnit(0, displayImage);
  program_.set("u_texel", glm::vec2(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)));
  gl::drawFullscreenTriangle(program_.id(), emptyVao_.id());
  scissorOff();
  timer_.end();
}

}  // namespace marble
