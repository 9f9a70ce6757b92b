#pragma once
// Mouse and keyboard in the 3D view. Keys are polled through GLFW (Debian's ImGui 1.86 has no
// named-key API we can rely on) and only act when ImGui does not want the keyboard (typing in
// a path box must not trigger shortcuts). Every shortcut here is listed in the help overlay.
#include <iterator>

#include "viewer_state.h"

struct GLFWwindow;

namespace marble {

// Left drag orbits, Shift+left or right drag moves the light, middle drag (or Ctrl+left) pans.
// A drag counts only if it starts in the 3D view (right of the panel, not over any ImGui window).
class MouseControl {
public:
  void update(GLFWwindow* w, ViewerState& s);
  bool dragging() const { return dragging_; }

private:
  double lastX_ = 0, lastY_ = 0;
  bool dragging_ = false;
};

// Key presses as edges (down this frame, up the last), polled once per frame.
class KeyEdges {
public:
  void update(GLFWwindow* w);
  bool pressed(int key) const;

private:
  static constexpr int kKeys[] = {256 /*ESC*/, 290 /*F1*/, 47 /*/ and ?*/, 301 /*F12*/, 70 /*F*/, 82 /*R*/,
                                  90 /*Z*/, 89 /*Y*/, 84 /*T*/, 258 /*TAB*/, 268 /*HOME*/};
  bool down_[std::size(kKeys)] = {};
  bool edge_[std::size(kKeys)] = {};
};

// Applies this frame's shortcuts to `s` (requests and toggles); `viewAspect` is for framing.
void handleShortcuts(GLFWwindow* w, const KeyEdges& keys, ViewerState& s, float viewAspect);

// The wheel zooms the camera unless ImGui wants it (scrolling the panel).
void installScrollZoom(GLFWwindow* w);

}  // namespace marble
