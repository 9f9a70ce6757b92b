#include "marble/gl/debug_output.h"

#include "marble/gl/draw_state_check.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace marble::gl {
namespace {

DebugHandler& currentHandler() {
  static DebugHandler handler;
  return handler;
}

const char* typeName(GLenum t) {
  switch (t) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated behaviour";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    case GL_DEBUG_TYPE_MARKER: return "marker";
    case GL_DEBUG_TYPE_PUSH_GROUP: return "push group";
    case GL_DEBUG_TYPE_POP_GROUP: return "pop group";
    default: return "other";
  }
}

const char* severityName(GLenum s) {
  switch (s) {
    case GL_DEBUG_SEVERITY_HIGH: return "high";
    case GL_DEBUG_SEVERITY_MEDIUM: return "medium";
    case GL_DEBUG_SEVERITY_LOW: return "low";
    default: return "notification";
  }
}

const char* sourceName(GLenum s) {
  switch (s) {
    case GL_DEBUG_SOURCE_API: return "API";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
  }
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void*) {
  const DebugHandler& handler = currentHandler();
  if (!handler) return;
  DebugMessage m{source, type, severity, id,
                 length >= 0 ? std::string(message, static_cast<size_t>(length)) : std::string(message)};
  while (!m.text.empty() && (m.text.back() == '\n' || m.text.back() == '\r')) m.text.pop_back();
  handler(m);
}

}  // namespace

bool isSevere(const DebugMessage& m) {
  if (m.source == GL_DEBUG_SOURCE_SHADER_COMPILER) return false;  // also a ShaderError, with file and line
  return m.type == GL_DEBUG_TYPE_ERROR || m.type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR ||
         m.severity == GL_DEBUG_SEVERITY_HIGH;
}

bool isWorthReporting(const DebugMessage& m) {
  if (m.source == GL_DEBUG_SOURCE_SHADER_COMPILER) return false;  // the ShaderError says it, once
  return m.severity != GL_DEBUG_SEVERITY_NOTIFICATION || isSevere(m);
}

std::string describe(const DebugMessage& m) {
  return std::string("GL debug: ") + typeName(m.type) + " (" + severityName(m.severity) + ", " + sourceName(m.source) +
         ", id " + std::to_string(m.id) + "): " + m.text;
}

void printDebugMessage(const DebugMessage& m) {
  if (isWorthReporting(m)) std::fprintf(stderr, "%s\n", describe(m).c_str());
}

void deliverDebugMessage(const DebugMessage& m) {
  if (const DebugHandler& handler = currentHandler()) handler(m);
}

void enableDebugOutput(DebugHandler handler) {
  currentHandler() = std::move(handler);
  drawStateChecksOn = true;
  glEnable(GL_DEBUG_OUTPUT);
  // Synchronous: the message arrives on this thread, inside the call that caused it (a
  // debugger's backtrace then shows the culprit, and a test's handler runs in the test).
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void disableDebugOutput() {
  glDebugMessageCallback(nullptr, nullptr);
  glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDisable(GL_DEBUG_OUTPUT);
  drawStateChecksOn = false;
  currentHandler() = nullptr;
}

bool debugOutputWanted() {
#ifndef NDEBUG
  return true;
#else
  const char* v = std::getenv("MARBLE_GL_DEBUG");
  return v && *v && std::strcmp(v, "0") != 0;
#endif
}

}  // namespace marble::gl
