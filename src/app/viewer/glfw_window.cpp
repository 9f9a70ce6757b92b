#include "glfw_window.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <cstdlib>

#include "marble/core/error.h"
#include "marble/gl/debug_output.h"

namespace marble {
namespace {
std::string g_lastGlfwError;
void onGlfwError(int, const char* description) { g_lastGlfwError = description ? description : "unknown"; }
}  // namespace

bool GlfwWindow::displayAvailable() {
  const char* x = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (w && *w);
}

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) throw EnvironmentError("cannot open a window: " + g_lastGlfwError);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  // A debug context makes drivers report everything they notice (gl/debug_output.h).
  if (gl::debugOutputWanted()) glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw EnvironmentError("cannot create an OpenGL 4.5 core window: " + g_lastGlfwError);
  }
  glfwMakeContextCurrent(window_);
  if (epoxy_gl_version() < 45) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw EnvironmentError("the window's OpenGL is older than 4.5 core");
  }
  if (gl::debugOutputWanted()) gl::enableDebugOutput();
}

GlfwWindow::~GlfwWindow() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

}  // namespace marble
