#include "viewer_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include "viewer_actions.h"

namespace marble {
namespace {

static_assert(GLFW_KEY_ESCAPE == 256 && GLFW_KEY_F1 == 290 && GLFW_KEY_SLASH == 47 && GLFW_KEY_F12 == 301 &&
              GLFW_KEY_F == 70 && GLFW_KEY_R == 82 && GLFW_KEY_Z == 90 && GLFW_KEY_Y == 89 && GLFW_KEY_T == 84 &&
              GLFW_KEY_TAB == 258 && GLFW_KEY_HOME == 268, "KeyEdges::kKeys spells GLFW's key codes");

bool held(GLFWwindow* w, int a, int b) { return glfwGetKey(w, a) == GLFW_PRESS || glfwGetKey(w, b) == GLFW_PRESS; }

void onScroll(GLFWwindow* w, double dx, double dy) {
  ImGui_ImplGlfw_ScrollCallback(w, dx, dy);
  if (ImGui::GetIO().WantCaptureMouse) return;
  static_cast<ViewerState*>(glfwGetWindowUserPointer(w))->camera.zoom(static_cast<float>(dy));
}

}  // namespace

void MouseControl::update(GLFWwindow* w, ViewerState& s) {
  double x, y;
  glfwGetCursorPos(w, &x, &y);
  const bool left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  const bool middle = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  const bool shift = held(w, GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
  const bool ctrl = held(w, GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
  const bool any = left || right || middle;
  if (any && !dragging_ && (ImGui::GetIO().WantCaptureMouse || x < s.panelWidth)) return;  // started on the UI
  if (any && dragging_) {
    const float dx = static_cast<float>(x - lastX_), dy = static_cast<float>(y - lastY_);
    if ((left && shift) || right) s.light.rotate(-dx * 0.4f, dy * 0.4f);
    else if (middle || (left && ctrl)) s.camera.pan(-dx * 0.002f, dy * 0.002f);
    else if (left) s.camera.rotate(-dx * 0.4f, dy * 0.4f);
  }
  dragging_ = any;
  lastX_ = x;
  lastY_ = y;
}

void KeyEdges::update(GLFWwindow* w) {
  for (size_t i = 0; i < std::size(kKeys); ++i) {
    const bool now = glfwGetKey(w, kKeys[i]) == GLFW_PRESS;
    edge_[i] = now && !down_[i];
    down_[i] = now;
  }
}

bool KeyEdges::pressed(int key) const {
  for (size_t i = 0; i < std::size(kKeys); ++i)
    if (kKeys[i] == key) return edge_[i];
  return false;
}

void handleShortcuts(GLFWwindow* w, const KeyEdges& keys, ViewerState& s, float viewAspect) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;  // typing in a box: ImGui's own Ctrl+Z applies there
  const bool ctrl = held(w, GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
  const bool shift = held(w, GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
  if (keys.pressed(GLFW_KEY_ESCAPE)) {
    if (s.showHelp) s.showHelp = false;  // Escape closes the overlay first, then the viewer
    else glfwSetWindowShouldClose(w, GLFW_TRUE);
  }
  if (keys.pressed(GLFW_KEY_F1) || keys.pressed(GLFW_KEY_SLASH)) s.showHelp = !s.showHelp;
  if (keys.pressed(GLFW_KEY_F12)) s.requestScreenshot = true;
  if (keys.pressed(GLFW_KEY_F) && !ctrl) frameObject(s, viewAspect);
  if (keys.pressed(GLFW_KEY_HOME)) s.camera = s.initialCamera;
  if (keys.pressed(GLFW_KEY_R) && !ctrl) {
    if (s.devMode) s.requestShaderReload = true;
    else s.setStatus("R reloads shaders in development mode only (marble view --dev)");
  }
  if (keys.pressed(GLFW_KEY_T) && !ctrl)
    s.turntable = s.turntable == Turntable::Off ? Turntable::Object : Turntable::Off;
  if (keys.pressed(GLFW_KEY_TAB)) s.showPanel = !s.showPanel;
  if (ctrl && keys.pressed(GLFW_KEY_Z)) (shift ? s.requestRedo : s.requestUndo) = true;
  if (ctrl && keys.pressed(GLFW_KEY_Y)) s.requestRedo = true;
}

void installScrollZoom(GLFWwindow* w) { glfwSetScrollCallback(w, onScroll); }

}  // namespace marble
