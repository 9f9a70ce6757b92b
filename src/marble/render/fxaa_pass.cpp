#include "marble/render/fxaa_pass.h"

#include "marble/render/shader_constants.h"

#include <cstdio>
#include <cstdlib>

namespace marble {

namespace {
// Steps of the edge search each way (shaders/fxaa.frag.glsl, searchStep): 1, 1, 1, 1, 1.5, 2, 2,
// 2, 4, 8 texels, 23.5 in all, about the reach of Lottes' default quality preset.
constexpr int kSearchSteps = 10;
}  // namespace

FxaaPass::FxaaPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "screen_spans.vert.glsl"}, {GL_FRAGMENT_SHADER, "fxaa.frag.glsl"}}),
      edgesProgram_(shaders, {{GL_VERTEX_SHADER, "screen_spans.vert.glsl"}, {GL_FRAGMENT_SHADER, "fxaa_edges.frag.glsl"}}),
      triProgram_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "fxaa.frag.glsl"}}),
      triEdgesProgram_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "fxaa_edges.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()),
      pointsProgram_(shaders, {{GL_VERTEX_SHADER, "screen_points.vert.glsl"}, {GL_FRAGMENT_SHADER, "fxaa.frag.glsl"}}),
      pointsVao_(gl::VertexArray::create()),
      pointsBuffer_(gl::Buffer::create()),
      spansVao_(gl::VertexArray::create()),
      spansBuffer_(gl::Buffer::create()) {
  program_.set("u_search_steps", kSearchSteps);
  triProgram_.set("u_search_steps", kSearchSteps);
  pointsProgram_.set("u_search_steps", kSearchSteps);
  glVertexArrayVertexBuffer(pointsVao_.id(), 0, pointsBuffer_.id(), 0, sizeof(glm::vec2));
  glEnableVertexArrayAttrib(pointsVao_.id(), 0);
  glVertexArrayAttribFormat(pointsVao_.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(pointsVao_.id(), 0, 0);
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
    std::vector<glm::vec2> centres;
    for (const ScreenRect& s : spans)
      for (int x = s.x; x < s.x + s.width; x += 16) centres.emplace_back(x + 8.0f, s.y + 8.0f);
    glNamedBufferData(pointsBuffer_.id(), static_cast<GLsizeiptr>(centres.size() * sizeof(glm::vec2)), centres.data(),
                      GL_DYNAMIC_DRAW);
    pointCount_ = centres.size();
  }
  if (std::getenv("FXAA_COUNT")) {
    long px = 0;
    for (const ScreenRect& s : spans) px += static_cast<long>(s.width) * s.height;
    std::fprintf(stderr, "spans %zu pixels %ld blocks %ld\n", spans.size(), px, px / 16);
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
  glBindVertexArray(spansVao_.id());
  static const bool twoPass = std::getenv("FXAA2") != nullptr;
  static const bool scissored = std::getenv("FXAA_SCISSOR") != nullptr;
  const glm::vec2 texel(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height));
  static const bool points = std::getenv("FXAA_POINTS") != nullptr;
  if (points) {
    pointsProgram_.set("u_texel", texel);
    pointsProgram_.set("u_target_size", glm::vec2(width, height));
    glPointSize(16.0f);
    glUseProgram(pointsProgram_.id());
    glBindVertexArray(pointsVao_.id());
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(pointCount_));
  } else if (scissored && !twoPass) {
    triProgram_.set("u_texel", texel);
    for (const ScreenRect& s : spans) {
      scissorTo(s);
      gl::drawFullscreenTriangle(triProgram_.id(), emptyVao_.id());
    }
    scissorOff();
  } else if (scissored && twoPass) {
    if (marksWidth_ != width || marksHeight_ != height) {
      marks_ = gl::makeTexture2D(GL_DEPTH_COMPONENT16, width, height, GL_NEAREST);
      marksWidth_ = width;
      marksHeight_ = height;
    }
    glNamedFramebufferTexture(targetFbo, GL_DEPTH_ATTACHMENT, marks_.id(), 0);
    triEdgesProgram_.set("u_texel", texel);
    triProgram_.set("u_texel", texel);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    for (const ScreenRect& s : spans) {
      scissorTo(s);
      gl::drawFullscreenTriangle(triEdgesProgram_.id(), emptyVao_.id());
    }
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    for (const ScreenRect& s : spans) {
      scissorTo(s);
      gl::drawFullscreenTriangle(triProgram_.id(), emptyVao_.id());
    }
    scissorOff();
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glNamedFramebufferTexture(targetFbo, GL_DEPTH_ATTACHMENT, 0, 0);
  } else if (twoPass && targetFbo != 0) {
    if (marksWidth_ != width || marksHeight_ != height) {
      marks_ = gl::makeTexture2D(GL_DEPTH_COMPONENT16, width, height, GL_NEAREST);
      marksWidth_ = width;
      marksHeight_ = height;
    }
    glNamedFramebufferTexture(targetFbo, GL_DEPTH_ATTACHMENT, marks_.id(), 0);
    edgesProgram_.set("u_texel", glm::vec2(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)));
    edgesProgram_.set("u_target_size", glm::vec2(width, height));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glUseProgram(edgesProgram_.id());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(spans.size() * 6));
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glUseProgram(program_.id());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(spans.size() * 6));
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glNamedFramebufferTexture(targetFbo, GL_DEPTH_ATTACHMENT, 0, 0);
  } else {
    glUseProgram(program_.id());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(spans.size() * 6));
  }
  timer_.end();
}

}  // namespace marble
