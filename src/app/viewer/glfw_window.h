#pragma once
// The viewer's window: GLFW with an OpenGL 4.5 core context, made current. Creation
// failures become one-line EnvironmentErrors (no display, no GL 4.5).
#include <string>

struct GLFWwindow;

namespace marble {

class GlfwWindow {
public:
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;
  GLFWwindow* handle() const { return window_; }

  // Whether a display server is reachable at all (checked before GLFW prints its own errors).
  static bool displayAvailable();

private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace marble
