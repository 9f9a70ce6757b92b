#include "marble/render/fxaa_pass.h"

#include "marble/gl/checked_calls.h"
#include "marble/render/shader_constants.h"

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

void FxaaPass::run(GLuint displayImage, GLuint targetFbo, int width, int height, const std::vector<ScreenRect>& spans,
                   const glm::vec3& background) {
  timer_.begin();
  gl::setScreenPassState();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glViewport(0, 0, width, height);
  // llvmpipe runs the whole edge search for every pixel it shades (both sides of every branch),
  // so the flat background outside the spans is cleared instead of filtered.
  const glm::vec4 clear(background, 1.0f);
  scissorTo({0, 0, width, height});  // the target may be larger than the frame
  gl::clearBoundFramebuffer(GL_COLOR, 0, &clear.x);
  glBindTextureUnit(shader::UNIT_SCREEN_INPUT, displayImage);
  program_.set("u_texel", glm::vec2(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)));
  // Each span is the full-screen triangle scissored to it, not two triangles of its own: llvmpipe
  // shades a 4x4 block once per triangle that covers part of it, so the blocks a rectangle's
  // diagonal crosses were shaded twice (the dragon at 800x800: 12,924 block calls for 10,800
  // blocks; callgrind). A scissor edge lies on the spans' 16-pixel grid, on whole blocks.
  for (const ScreenRect& s : spans) {
    scissorTo(s);
    gl::drawFullscreenTriangle(program_.id(), emptyVao_.id());
  }
  scissorOff();
  timer_.end();
}

}  // namespace marble
