#pragma once
// Shared by the GL tests: one headless context per test binary (EGL on llvmpipe here; a GL
// test that cannot get a context fails, it does not skip), with KHR_debug output on, and a
// render-to-image helper.
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "marble/gl/checked_calls.h"
#include "marble/gl/debug_output.h"
#include "marble/gl/draw_state_check.h"
#include "marble/gl/handles.h"
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

// One shader stage from its source: the compiler's log as a test failure and 0 where it does not
// compile. The caller deletes it.
inline GLuint compileShaderStage(GLenum stage, const std::string& source) {
  const char* text = source.c_str();
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    ADD_FAILURE() << "shader stage " << stage << ": " << log;
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

// A program of the given compiled stages, which it deletes: a link failure is a test failure.
inline GLuint linkTestProgram(std::initializer_list<GLuint> stages) {
  const GLuint program = glCreateProgram();
  for (GLuint stage : stages) glAttachShader(program, stage);
  glLinkProgram(program);
  for (GLuint stage : stages) glDeleteShader(stage);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  EXPECT_TRUE(ok) << "test program did not link";
  return program;
}

// Deletes a test's program. GL keeps a deleted program in use while it is current (OpenGL 4.5,
// 7.3), so it is unbound first: left current, the next test's first clear would check its samplers
// against units its owner no longer fills (the draw state check reports it, as NVIDIA's driver
// would). Its sampler record goes too, since GL reuses the name.
inline void deleteTestProgram(GLuint program) {
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  if (static_cast<GLuint>(current) == program) glUseProgram(0);
  gl::forgetProgramSamplers(program);
  glDeleteProgram(program);
}

// A compute program from one source string, for the tests that wrap a library file in a shader
// of their own (pattern_gl_test, nearest_texel_gl_test): 0 where it does not compile, a compile or
// link failure a test failure. The caller deletes it.
inline GLuint compileComputeProgram(const std::string& source) {
  const GLuint shader = compileShaderStage(GL_COMPUTE_SHADER, source);
  return shader ? linkTestProgram({shader}) : 0;
}

// The fixture of the tests that wrap library shader files in a compute shader of their own
// (nearest_texel_gl_test, transmission_chord_gl_test, mirror_hit_light_gl_test): compileProgram in
// SetUp (the source after its #version line), the program deleted after the test.
class ComputeProgramTest : public ::testing::Test {
protected:
  void compileProgram(const std::string& source) {
    glContext();  // the test binary's one context, debug output on
    program_ = compileComputeProgram("#version 450 core\n" + source);
    ASSERT_NE(program_, 0u);
  }
  void TearDown() override { deleteTestProgram(program_); }
  GLuint program_ = 0;
};

// The compute shader main of a runPerVec4 test: one invocation a query, `q` the query's vec4 (binding
// 0), `body` the statements that write `results[i]` (binding 1).
inline std::string perVec4Main(const std::string& body) {
  return "layout(local_size_x = 1) in;\n"
         "layout(std430, binding = 0) readonly buffer Queries { vec4 queries[]; };\n"
         "layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };\n"
         "void main() {\n  uint i = gl_GlobalInvocationID.x;\n  vec4 q = queries[i];\n" +
         body + "\n}\n";
}

// Runs `program` (already bound to its textures and uniforms) once per vec4 of `in`: one work group a
// vec4, the inputs at shader-storage binding 0 and as many vec4 results at binding 1, which it
// returns (the tests that query one library function at a list of points: transmission_chord_gl_test,
// mirror_hit_light_gl_test).
inline std::vector<float> runPerVec4(GLuint program, const std::vector<float>& in) {
  const auto bytes = static_cast<GLsizeiptr>(in.size() * sizeof(float));
  gl::Buffer inBuf = gl::Buffer::create(), outBuf = gl::Buffer::create();
  glNamedBufferStorage(inBuf.id(), bytes, in.data(), 0);
  glNamedBufferStorage(outBuf.id(), bytes, nullptr, GL_MAP_READ_BIT);
  glUseProgram(program);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, inBuf.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, outBuf.id());
  gl::dispatchCompute(static_cast<GLuint>(in.size() / 4), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> out(in.size());
  glGetNamedBufferSubData(outBuf.id(), 0, bytes, out.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return out;
}

inline ImageRGBA8 renderImage(Renderer& renderer, const Scene& scene) {
  glContext();
  OffscreenTarget target(scene.render.width, scene.render.height);
  renderer.render(scene, glm::mat4(1.0f), target.fbo(), target.width(), target.height());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return target.read();
}

// The HDR frame of `scene` drawn by `renderer` with the model matrix `model`, read back.
inline ImageRGBF renderHdr(Renderer& renderer, const Scene& scene, const glm::mat4& model) {
  OffscreenTarget target(scene.render.width, scene.render.height);
  renderer.render(scene, model, target.fbo(), target.width(), target.height());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return renderer.readHdr();
}

// One scene drawn by two renderers that must give the same frame (a saving that may not change a
// value: face_culling_gl_test, screen_cull_gl_test), each frame read back before the other draws.
// differingValues: the values (pixel channels) that are not bit-equal; litPixels: the second
// frame's pixels with any light (the HDR frame's background is black), to show the view saw the mesh.
struct FramePairDifference {
  size_t differingValues = 0;
  size_t litPixels = 0;
};
inline FramePairDifference compareFrames(Renderer& first, Renderer& second, const Scene& scene,
                                         const glm::mat4& model) {
  glContext();
  const ImageRGBF a = renderHdr(first, scene, model);
  const ImageRGBF b = renderHdr(second, scene, model);
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  FramePairDifference d;
  for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i) d.differingValues += a.pixels[i] != b.pixels[i];
  for (size_t i = 0; i + 2 < b.pixels.size(); i += 3) d.litPixels += b.pixels[i] + b.pixels[i + 1] + b.pixels[i + 2] > 0.0f;
  return d;
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
