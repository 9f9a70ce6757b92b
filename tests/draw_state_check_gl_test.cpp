// The draw state check (gl/draw_state_check.h): what NVIDIA's driver reports at a draw whose
// program has an active sampler with nothing fitting on its unit, reported here on any driver.
// llvmpipe says nothing of it, so without the check these mistakes pass every test here and fail
// on a GPU (58 of 129 GL tests did, docs/performance.md "GPU measured: NVIDIA H200, session 17").
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl_support.h"
#include "marble/gl/debug_output.h"
#include "marble/gl/draw_state_check.h"
#include "marble/gl/handles.h"
#include "marble/mesh/mesh.h"
#include "marble/render/offscreen_target.h"
#include "marble/render/renderer.h"

namespace marble {
namespace {

using test::glContext;
using test::RecordedMessages;

constexpr int kShadowUnit = 4, kColorUnit = 5;

constexpr const char* kVertex = R"(#version 450 core
void main() { gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0); }
)";
// Reads the shadow sampler only where u_read_shadow is set: NVIDIA checks the unit either way,
// and so does the check (the test draws with it off).
constexpr const char* kFragment = R"(#version 450 core
layout(binding = 4) uniform sampler2DShadow u_shadow;
layout(binding = 5) uniform sampler2D u_color;
uniform int u_read_shadow;
out vec4 color;
void main() {
  color = texture(u_color, vec2(0.5));
  if (u_read_shadow != 0) color.r = texture(u_shadow, vec3(0.5, 0.5, 0.5));
}
)";

GLuint compile(GLenum stage, const char* text) {
  const GLuint s = glCreateShader(stage);
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  EXPECT_TRUE(ok);
  return s;
}

gl::ProgramId shadowProgram() {
  gl::ProgramId p = gl::ProgramId::create();
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertex), fs = compile(GL_FRAGMENT_SHADER, kFragment);
  glAttachShader(p.id(), vs);
  glAttachShader(p.id(), fs);
  glLinkProgram(p.id());
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
  EXPECT_TRUE(ok);
  const std::string label = "draw state test program";
  glObjectLabel(GL_PROGRAM, p.id(), static_cast<GLsizei>(label.size()), label.c_str());
  return p;
}

gl::Texture depthTexture(bool compare) {
  gl::Texture t = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, 1, 1, GL_LINEAR);
  const float one = 1.0f;
  glClearTexImage(t.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  if (compare) glTextureParameteri(t.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  return t;
}

gl::Texture colorTexture() {
  gl::Texture t = gl::makeTexture2D(GL_RGBA8, 1, 1, GL_LINEAR);
  const uint8_t c[4] = {10, 20, 30, 255};
  glClearTexImage(t.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  return t;
}

// Draws the program once with whatever the two units hold; the check's reports.
std::vector<gl::DebugMessage> drawWith(GLuint shadowTexture, GLuint colorTexture) {
  OffscreenTarget target(4, 4);
  gl::ProgramId program = shadowProgram();
  gl::VertexArray vao = gl::VertexArray::create();
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo());
  glViewport(0, 0, 4, 4);
  gl::setScreenPassState();
  glBindTextureUnit(kShadowUnit, shadowTexture);
  glBindTextureUnit(kColorUnit, colorTexture);
  std::vector<gl::DebugMessage> reports;
  {
    RecordedMessages recorded;
    gl::drawFullscreenTriangle(program.id(), vao.id());
    for (const gl::DebugMessage& m : recorded.messages)
      if (m.source == GL_DEBUG_SOURCE_APPLICATION) reports.push_back(m);
  }
  glBindTextureUnit(kShadowUnit, 0);
  glBindTextureUnit(kColorUnit, 0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return reports;
}

std::string all(const std::vector<gl::DebugMessage>& reports) {
  std::string s;
  for (const auto& m : reports) s += gl::describe(m) + "\n";
  return s;
}

struct DrawStateCheck : ::testing::Test {
  HeadlessContext& context = glContext();
};

TEST_F(DrawStateCheck, AnEmptyShadowUnitIsReportedWithProgramUniformAndUnit) {
  const gl::Texture color = colorTexture();
  const auto reports = drawWith(0, color.id());
  ASSERT_EQ(reports.size(), 1u) << all(reports);
  const gl::DebugMessage& m = reports.front();
  EXPECT_TRUE(gl::isSevere(m)) << "a GL test fails on it, as on NVIDIA";
  EXPECT_EQ(m.id, static_cast<GLuint>(gl::kNothingBound));
  const std::string line = gl::describe(m);
  EXPECT_NE(line.find("draw state test program"), std::string::npos) << line;
  EXPECT_NE(line.find("sampler2DShadow u_shadow on unit 4"), std::string::npos) << line;
}

TEST_F(DrawStateCheck, AFittingDepthTextureWithComparisonsOnReportsNothing) {  // the negative control
  const gl::Texture depth = depthTexture(true);
  const gl::Texture color = colorTexture();
  const auto reports = drawWith(depth.id(), color.id());
  EXPECT_TRUE(reports.empty()) << all(reports);
}

TEST_F(DrawStateCheck, AShadowSamplerOverAColourOrAnUncomparedDepthTextureIsReported) {
  const gl::Texture color = colorTexture();
  auto reports = drawWith(color.id(), color.id());
  ASSERT_EQ(reports.size(), 1u) << all(reports);
  EXPECT_EQ(reports.front().id, static_cast<GLuint>(gl::kShadowWithoutDepth));
  const gl::Texture uncompared = depthTexture(false);
  reports = drawWith(uncompared.id(), color.id());
  ASSERT_EQ(reports.size(), 1u) << all(reports);
  EXPECT_EQ(reports.front().id, static_cast<GLuint>(gl::kShadowWithoutCompare));
  // A sampler object's state stands for the texture's: comparisons on through it are enough.
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glBindSampler(kShadowUnit, sampler);
  reports = drawWith(uncompared.id(), color.id());
  glBindSampler(kShadowUnit, 0);
  glDeleteSamplers(1, &sampler);
  EXPECT_TRUE(reports.empty()) << all(reports);
}

TEST_F(DrawStateCheck, ComparisonsUnderAPlainSamplerAndIncompleteOrIntegerTexturesAreReported) {
  const gl::Texture depth = depthTexture(true);
  auto reports = drawWith(depth.id(), depth.id());  // the colour sampler reads a comparing depth texture
  ASSERT_EQ(reports.size(), 1u) << all(reports);
  EXPECT_EQ(reports.front().id, static_cast<GLuint>(gl::kCompareWithoutShadow));
  EXPECT_NE(gl::describe(reports.front()).find("sampler2D u_color on unit 5"), std::string::npos);

  gl::Texture noLevels = gl::Texture::create(GL_TEXTURE_2D);  // created, never given storage
  reports = drawWith(depth.id(), noLevels.id());
  ASSERT_EQ(reports.size(), 1u) << all(reports);
  EXPECT_EQ(reports.front().id, static_cast<GLuint>(gl::kIncomplete));

  gl::Texture integer = gl::makeTexture2D(GL_RGBA8UI, 1, 1, GL_NEAREST);
  const uint8_t c[4] = {1, 2, 3, 4};
  glClearTexImage(integer.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, c);
  reports = drawWith(depth.id(), integer.id());
  ASSERT_EQ(reports.size(), 1u) << all(reports);
  EXPECT_EQ(reports.front().id, static_cast<GLuint>(gl::kWrongComponentType));
}

// What failed 58 GL tests on NVIDIA: a renderer's last program (the post pass's, with its shadow
// sampler) stayed current after its frame, the renderer went with its textures, and the driver
// checked the program again at the next renderer's first clear. The check runs at clears too;
// the negative control: a program left current with an empty shadow unit is reported there.
TEST_F(DrawStateCheck, AProgramLeftCurrentIsCheckedAtTheNextClear) {
  const gl::ProgramId left = shadowProgram();
  const gl::Texture color = colorTexture();
  glBindTextureUnit(kShadowUnit, 0);
  glBindTextureUnit(kColorUnit, color.id());
  glUseProgram(left.id());
  Scene scene;
  scene.render.width = scene.render.height = 16;
  Renderer renderer;
  renderer.setMesh(builtinMesh("sphere"));
  OffscreenTarget target(16, 16);
  std::vector<gl::DebugMessage> reports;
  {
    RecordedMessages recorded;
    renderer.render(scene, glm::mat4(1.0f), target.fbo(), 16, 16);
    for (const gl::DebugMessage& m : recorded.messages)
      if (m.source == GL_DEBUG_SOURCE_APPLICATION) reports.push_back(m);
  }
  glBindTextureUnit(kColorUnit, 0);
  ASSERT_FALSE(reports.empty()) << "the renderer's first clear found the program left current";
  EXPECT_NE(gl::describe(reports.front()).find("sampler2DShadow u_shadow on unit 4"), std::string::npos)
      << all(reports);
}

// The fix: the renderer's entry points that draw leave no program current, so nothing of a frame
// is checked again once its textures are gone (and a second renderer's frames report nothing).
TEST_F(DrawStateCheck, ARendererLeavesNoProgramCurrent) {
  Scene scene;
  scene.render.width = scene.render.height = 16;
  scene.render.mode = RenderMode::Marble;
  auto currentProgram = [] {
    GLint p = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &p);
    return p;
  };
  {
    Renderer first;
    first.setMesh(builtinMesh("sphere"));
    test::renderImage(first, scene);
    EXPECT_EQ(currentProgram(), 0) << "after render";
    first.readHdr();
    EXPECT_EQ(currentProgram(), 0) << "after readHdr";
  }
  Renderer second;  // the suite's test handler fails this test on any report
  second.setMesh(builtinMesh("sphere"));
  test::renderImage(second, scene);
  EXPECT_EQ(currentProgram(), 0);
}

// A new render target's contents are undefined; on a GPU they are often a freed texture's. With the
// checks on, each new one holds a value of its own (not llvmpipe's zeros), so a frame that read a
// texel it never wrote would differ from a fresh one in the exact-equality tests here too.
TEST_F(DrawStateCheck, ANewTextureHoldsAValueOfItsOwnNotZero) {
  auto firstTexel = [](GLuint texture) {
    float rgba[4] = {};
    glGetTextureSubImage(texture, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof rgba, rgba);
    return glm::vec4(rgba[0], rgba[1], rgba[2], rgba[3]);
  };
  const gl::Texture a = gl::makeTexture2D(GL_RGBA16F, 2, 2, GL_NEAREST);
  const gl::Texture b = gl::makeTexture2D(GL_RGBA16F, 2, 2, GL_NEAREST);
  EXPECT_NE(firstTexel(a.id()), glm::vec4(0.0f));
  EXPECT_NE(firstTexel(a.id()), firstTexel(b.id()));
}

TEST_F(DrawStateCheck, ItIsOnExactlyWhileTheDebugOutputIs) {
  ASSERT_TRUE(gl::drawStateChecksOn) << "the GL tests run with it";
  gl::disableDebugOutput();
  EXPECT_FALSE(gl::drawStateChecksOn);
  gl::enableDebugOutput(test::failOnSevereGlMessages);
  EXPECT_TRUE(gl::drawStateChecksOn);
}

}  // namespace
}  // namespace marble
