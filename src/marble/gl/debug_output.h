#pragma once
// KHR_debug (core since OpenGL 4.3): the driver reports errors and undefined behaviour as they
// happen, inside the call that caused them, instead of a later glGetError that says only
// "something failed". On in debug builds (HeadlessContext, the viewer's window) and in the GL
// tests, where a severe message fails the running test (tests/gl_support.h); MARBLE_GL_DEBUG=1
// turns it on in a release build. Costs nothing when off; synchronous output slows a driver
// down, so release builds leave it off.
#include <epoxy/gl.h>

#include <functional>
#include <string>

namespace marble::gl {

struct DebugMessage {
  GLenum source = 0;    // GL_DEBUG_SOURCE_API, ..._SHADER_COMPILER, ...
  GLenum type = 0;      // GL_DEBUG_TYPE_ERROR, ..._UNDEFINED_BEHAVIOR, ..._PERFORMANCE, ...
  GLenum severity = 0;  // GL_DEBUG_SEVERITY_HIGH, _MEDIUM, _LOW, _NOTIFICATION
  GLuint id = 0;
  std::string text;
};

// Errors and undefined behaviour at any severity, and anything of high severity: what a test
// must not produce. Notifications (llvmpipe sends some, e.g. about buffer placement) and
// low/medium performance or portability remarks are not severe, nor is the shader compiler's
// echo of a compile error: that reaches the caller as a ShaderError naming file and line.
bool isSevere(const DebugMessage& m);
// Worth a line on stderr: everything but notifications and the compiler's echo of a compile
// error (the ShaderError's one line says it; a second would break "one line per error").
bool isWorthReporting(const DebugMessage& m);
// One line: "GL debug: error (high, API, id 1280): <driver's text>".
std::string describe(const DebugMessage& m);

using DebugHandler = std::function<void(const DebugMessage&)>;
// Prints describe(m) to stderr for messages worth reporting.
void printDebugMessage(const DebugMessage& m);

// Sends `m` to the handler enableDebugOutput set (none: dropped), as the driver's messages go:
// marble's own checks (draw_state_check.h) report through it.
void deliverDebugMessage(const DebugMessage& m);

// Enables synchronous debug output on the current context and sends every message to
// `handler` (which filters); replaces a handler set before. The handler is process-wide
// (marble has one context per process).
void enableDebugOutput(DebugHandler handler = printDebugMessage);
// Also turns on the checks of draw_state_check.h before each draw and dispatch.
// Turns it off again on the current context (and those checks).
void disableDebugOutput();
// Whether this build wants it by default: a debug build (NDEBUG undefined), or MARBLE_GL_DEBUG
// set to a non-empty value other than 0.
bool debugOutputWanted();

}  // namespace marble::gl
