#include "marble/gl/headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <cstring>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "marble/core/error.h"
#include "marble/gl/debug_output.h"
#include "marble/gl/draw_state_check.h"

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif
#ifndef EGL_PLATFORM_DEVICE_EXT
#define EGL_PLATFORM_DEVICE_EXT 0x313F
#endif

namespace marble {
namespace {

using detail::CurrentEgl;

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// Candidate displays in order of preference: Mesa's surfaceless platform (no X, no GPU
// needed), then each EGL device (how NVIDIA's driver renders headless), then the default.
std::vector<EGLDisplay> candidateDisplays() {
  std::vector<EGLDisplay> out;
  const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (hasExtension(clientExts, "EGL_EXT_platform_base")) {
    if (hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) {
      EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (d != EGL_NO_DISPLAY) out.push_back(d);
    }
    if (hasExtension(clientExts, "EGL_EXT_platform_device") && hasExtension(clientExts, "EGL_EXT_device_enumeration")) {
      EGLDeviceEXT devices[8];
      EGLint count = 0;
      if (eglQueryDevicesEXT(8, devices, &count))
        for (EGLint i = 0; i < count; ++i) {
          EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
          if (d != EGL_NO_DISPLAY) out.push_back(d);
        }
    }
  }
  EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (d != EGL_NO_DISPLAY) out.push_back(d);
  return out;
}

// eglInitialize on a display that is already initialized does nothing, and one eglTerminate
// ends every context on it; eglGetPlatformDisplay hands the same EGLDisplay to everyone in the
// process who asks for the same platform. So a display is terminated only when the last
// HeadlessContext that initialized it goes: a context made and dropped (marble::render in
// marble.cpp makes one per call) must not end another one's, nor an embedding program's.
std::mutex gDisplayUsersMutex;
std::map<EGLDisplay, int> gDisplayUsers;

bool initializeDisplay(EGLDisplay display) {
  std::lock_guard lock(gDisplayUsersMutex);
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return false;
  ++gDisplayUsers[display];
  return true;
}

void terminateDisplay(EGLDisplay display) {
  std::lock_guard lock(gDisplayUsersMutex);
  const auto it = gDisplayUsers.find(display);
  if (it == gDisplayUsers.end() || --it->second > 0) return;
  gDisplayUsers.erase(it);
  eglTerminate(display);
}

// Gives back what a display and context hold, in reverse order of acquisition; either may be
// null (a display initialized but no context made yet). If the context is current, whatever was
// current before it was made is made current again (a context made and dropped inside another's
// use leaves that one working); if that fails, nothing is current.
void releaseEgl(EGLDisplay display, EGLContext context, const CurrentEgl& previous) {
  if (!display) return;
  if (context && eglGetCurrentContext() == context) {
    const bool restored = previous.context != EGL_NO_CONTEXT &&
                          eglMakeCurrent(previous.display, previous.draw, previous.read, previous.context);
    if (!restored) eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (context) eglDestroyContext(display, context);
  terminateDisplay(display);
}

// What one candidate display has acquired so far. Whatever a failed attempt holds is released
// when it goes out of scope (a `continue`, a throw); a successful one hands both over with
// release(), after which it owns nothing.
class EglAttempt {
public:
  explicit EglAttempt(const CurrentEgl& previous) : previous_(previous) {}
  ~EglAttempt() { releaseEgl(display_, context_, previous_); }
  EglAttempt(const EglAttempt&) = delete;
  EglAttempt& operator=(const EglAttempt&) = delete;

  void ownDisplay(EGLDisplay d) { display_ = d; }   // after initializeDisplay succeeded
  void ownContext(EGLContext c) { context_ = c; }
  std::pair<EGLDisplay, EGLContext> release() {
    return {std::exchange(display_, nullptr), std::exchange(context_, nullptr)};
  }

private:
  const CurrentEgl& previous_;
  EGLDisplay display_ = nullptr;
  EGLContext context_ = nullptr;
};

}  // namespace

HeadlessContext::HeadlessContext() {
  // Mesa prints multi-line warnings of its own while probing; our one line says what failed.
  setenv("EGL_LOG_LEVEL", "fatal", 0);
  std::string lastProblem = "no EGL display available (is libegl-mesa0 installed?)";
  previous_ = {eglGetCurrentDisplay(), eglGetCurrentSurface(EGL_DRAW), eglGetCurrentSurface(EGL_READ),
               eglGetCurrentContext()};
  for (EGLDisplay display : candidateDisplays()) {
    if (!initializeDisplay(display)) {
      // Keep an earlier, more telling reason (e.g. "no OpenGL 4.5 core context").
      if (lastProblem.rfind("no EGL display", 0) == 0) lastProblem = "eglInitialize failed";
      continue;
    }
    EglAttempt attempt(previous_);
    attempt.ownDisplay(display);
    if (!eglBindAPI(EGL_OPENGL_API)) {
      lastProblem = "EGL has no desktop OpenGL API";
      continue;
    }
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint numConfigs = 0;
    // With EGL_KHR_no_config_context / surfaceless, a config is optional; try one first.
    eglChooseConfig(display, configAttribs, &config, 1, &numConfigs);
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    EGLContext ctx = eglCreateContext(display, numConfigs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttribs);
    if (ctx == EGL_NO_CONTEXT) {
      lastProblem = "the driver offers no OpenGL 4.5 core context";
      continue;
    }
    attempt.ownContext(ctx);
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      lastProblem = "cannot make a surfaceless context current (EGL_KHR_surfaceless_context missing)";
      continue;
    }
    if (const int v = epoxy_gl_version(); v < 45)
      throw EnvironmentError("headless OpenGL: got version " + std::to_string(v / 10) + "." + std::to_string(v % 10) +
                             ", marble needs 4.5 core");  // `attempt` releases the context
    std::tie(display_, context_) = attempt.release();
    gl::forgetAllProgramSamplers();  // program names now name this context's objects
    if (gl::debugOutputWanted()) gl::enableDebugOutput();
    return;
  }
  throw EnvironmentError("headless OpenGL: " + lastProblem);
}

HeadlessContext::~HeadlessContext() {
  releaseEgl(display_, context_, previous_);
  gl::forgetAllProgramSamplers();  // and now the previous context's again
}

std::string HeadlessContext::renderer() const {
  const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return r ? r : "unknown";
}

}  // namespace marble
