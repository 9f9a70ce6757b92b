// KHR_debug output (gl/debug_output.h): every GL test runs with it on, and a severe message
// fails the test that caused it (gl_support.h). These check that the machinery does report: a
// handler that never fired would let the whole suite pass on a driver that says nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl_support.h"
#include "marble/gl/debug_output.h"

namespace marble {
namespace {

using test::glContext;
using test::RecordedMessages;

TEST(GlDebugOutput, AnInvalidCallIsReportedAsASevereErrorInsideTheCall) {
  glContext();
  RecordedMessages recorded;
  glEnable(0x1234);  // no such capability: GL_INVALID_ENUM
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  ASSERT_FALSE(recorded.messages.empty()) << "synchronous output reports before the call returns";
  const gl::DebugMessage& m = recorded.messages.front();
  EXPECT_EQ(m.type, static_cast<GLenum>(GL_DEBUG_TYPE_ERROR));
  EXPECT_TRUE(gl::isSevere(m));
  const std::string line = gl::describe(m);
  EXPECT_EQ(line.rfind("GL debug: error (", 0), 0u) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << "one line";
}

TEST(GlDebugOutput, ACorrectCallReportsNothingSevere) {  // the negative control
  glContext();
  RecordedMessages recorded;
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  for (const auto& m : recorded.messages) EXPECT_FALSE(gl::isSevere(m)) << gl::describe(m);
}

TEST(GlDebugOutput, SeverityDecidesWhatFailsATest) {
  gl::DebugMessage m;
  m.source = GL_DEBUG_SOURCE_API;
  m.type = GL_DEBUG_TYPE_OTHER;
  m.severity = GL_DEBUG_SEVERITY_NOTIFICATION;  // what llvmpipe says in passing
  EXPECT_FALSE(gl::isSevere(m));
  EXPECT_FALSE(gl::isWorthReporting(m));
  m.type = GL_DEBUG_TYPE_PERFORMANCE;
  m.severity = GL_DEBUG_SEVERITY_MEDIUM;
  EXPECT_FALSE(gl::isSevere(m));
  EXPECT_TRUE(gl::isWorthReporting(m));
  m.severity = GL_DEBUG_SEVERITY_HIGH;
  EXPECT_TRUE(gl::isSevere(m));
  m.type = GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR;
  m.severity = GL_DEBUG_SEVERITY_LOW;
  EXPECT_TRUE(gl::isSevere(m));
  // A compile error reaches the caller as a ShaderError naming file and line; the driver's
  // echo of it is not a second failure (tests compile broken shaders on purpose).
  m.source = GL_DEBUG_SOURCE_SHADER_COMPILER;
  m.type = GL_DEBUG_TYPE_ERROR;
  m.severity = GL_DEBUG_SEVERITY_HIGH;
  EXPECT_FALSE(gl::isSevere(m));
  EXPECT_FALSE(gl::isWorthReporting(m));
}

}  // namespace
}  // namespace marble
