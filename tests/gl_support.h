#pragma once
// Shared by the GL tests: one headless context per test binary (EGL on llvmpipe here; a GL
// test that cannot get a context fails, it does not skip), with KHR_debug output on, and a
// render-to-image helper.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "marble/gl/debug_output.h"
#include "marble/gl/headless_context.h"
#include "marble/render/offscreen_target.h"
#include "marble/render/renderer.h"

namespace marble::test {

// The GL tests' debug handler: a severe message (gl::isSevere: an error, undefined behaviour,
// anything of high severity) fails the running test with the driver's words; lesser ones other
// than notifications are printed.
inline void failOnSevereGlMessages(const gl::DebugMessage& m) {
  if (gl::isSevere(m))
    ADD_FAILURE() << gl::describe(m);
  else
    gl::printDebugMessage(m);
}

// Swaps in a handler that records the messages, for the span of one test, and puts the suite's
// handler back.
class RecordedMessages {
public:
  RecordedMessages() {
    gl::enableDebugOutput([this](const gl::DebugMessage& m) { messages.push_back(m); });
  }
  ~RecordedMessages() { gl::enableDebugOutput(failOnSevereGlMessages); }
  RecordedMessages(const RecordedMessages&) = delete;
  RecordedMessages& operator=(const RecordedMessages&) = delete;
  std::vector<gl::DebugMessage> messages;
};

inline HeadlessContext& glContext() {
  static std::unique_ptr<HeadlessContext> ctx = [] {
    auto c = std::make_unique<HeadlessContext>();
    gl::enableDebugOutput(failOnSevereGlMessages);
    return c;
  }();
  return *ctx;
}

// A compute program from one source string, for the tests that wrap a library file in a shader
// of their own (pattern_gl_test, nearest_texel_gl_test): the compiler's log as a test failure and
// 0 where it does not compile; a link failure is a test failure too. The caller deletes it.
inline GLuint compileComputeProgram(const std::string& source) {
  const char* text = source.c_str();
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    ADD_FAILURE() << "compute shader: " << log;
    glDeleteShader(shader);
    return 0;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  EXPECT_TRUE(ok) << "compute program did not link";
  return program;
}

inline ImageRGBA8 renderImage(Renderer& renderer, const Scene& scene) {
  glContext();
  OffscreenTarget target(scene.render.width, scene.render.height);
  renderer.render(scene, glm::mat4(1.0f), target.fbo(), target.width(), target.height());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return target.read();
}

// The HDR pictures of one scene drawn with two meshes (a fresh renderer each): a test that isolates
// the light one part sends subtracts the picture without that part from the picture with it.
struct HdrPair {
  ImageRGBF first, second;
};
inline HdrPair renderHdrPair(const Scene& scene, Mesh first, Mesh second) {
  HdrPair pair;
  Renderer a, b;
  a.setMesh(std::move(first));
  renderImage(a, scene);
  pair.first = a.readHdr();
  b.setMesh(std::move(second));
  renderImage(b, scene);
  pair.second = b.readHdr();
  return pair;
}

inline glm::vec3 pixel(const ImageRGBA8& img, int x, int y) {
  const auto p = img.at(x, y);
  return glm::vec3(p.r, p.g, p.b) / 255.0f;
}

inline double meanAbsDiff(const ImageRGBA8& a, const ImageRGBA8& b) {
  double sum = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
  return sum / static_cast<double>(a.pixels.size());
}

}  // namespace marble::test
