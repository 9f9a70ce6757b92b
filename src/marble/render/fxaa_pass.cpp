#include "marble/render/fxaa_pass.h"

#include "marble/render/shader_constants.h"

namespace marble {

namespace {
// Steps of the edge search each way (shaders/fxaa.frag.glsl, searchStep): 1, 1, 1, 1, 1.5, 2, 2,
// 2, 4, 8 texels, 23.5 in all, about the reach of Lottes' default quality preset.
constexpr int kSearchSteps = 10;
}  // namespace

FxaaPass::FxaaPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "screen_spans.vert.glsl"}, {GL_FRAGMENT_SHADER, "fxaa.frag.glsl"}}),
      spansVao_(gl::VertexArray::create()),
      spansBuffer_(gl::Buffer::create()) {
  program_.set("u_search_steps", kSearchSteps);
  glVertexArrayVertexBuffer(spansVao_.id(), 0, spansBuffer_.id(), 0, sizeof(glm::vec2));
  glEnableVertexArrayAttrib(spansVao_.id(), 0);
  glVertexArrayAttribFormat(spansVao_.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(spansVao_.id(), 0, 0);
}

void FxaaPass::run(GLuint displayImage, GLuint targetFbo, int width, int height, const std::vector<ScreenRect>& spans,
                   const glm::vec3& background) {
  if (spans != uploadedSpans_) {  // the view moved: two triangles per span, in pixels
    std::vector<glm::vec2> corners;
    corners.reserve(spans.size() * 6);
    for (const ScreenRect& s : spans) {
      const glm::vec2 a(s.x, s.y), b(s.x + s.width, s.y + s.height);
      for (const glm::vec2& c : {a, glm::vec2(b.x, a.y), b, a, b, glm::vec2(a.x, b.y)}) corners.push_back(c);
    }
    glNamedBufferData(spansBuffer_.id(), static_cast<GLsizeiptr>(corners.size() * sizeof(glm::vec2)), corners.data(),
                      GL_DYNAMIC_DRAW);
    uploadedSpans_ = spans;
  }
  timer_.begin();
  gl::setScreenPassState();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glViewport(0, 0, width, height);
  // llvmpipe runs the whole edge search for every pixel it shades (both sides of every branch),
  // so the flat background outside the spans is cleared instead of filtered.
  const glm::vec4 clear(background, 1.0f);
  scissorTo({0, 0, width, height});  // the target may be larger than the frame
  glClearBufferfv(GL_COLOR, 0, &clear.x);
  scissorOff();
  glBindTextureUnit(shader::UNIT_SCREEN_INPUT, displayImage);
  program_.set("u_texel", glm::vec2(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)));
  program_.set("u_target_size", glm::vec2(width, height));
  glUseProgram(program_.id());
  glBindVertexArray(spansVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(spans.size() * 6));
  timer_.end();
}

}  // namespace marble
