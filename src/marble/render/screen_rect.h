#pragma once
// The part of the frame a mesh can cover: the screen-space box of its bounding box's eight
// corners. Screen passes draw only inside it (scissor test). On llvmpipe a fragment shader's
// branches run under a mask, so testing "is this background?" per pixel saves nothing; a
// scissor rectangle skips whole tiles before any shading. On a GPU it saves bandwidth.
#include <glm/glm.hpp>

namespace marble {

struct ScreenRect {
  int x = 0, y = 0, width = 0, height = 0;  // pixels, origin bottom-left (GL's)
  bool operator==(const ScreenRect&) const = default;
  bool empty() const { return width <= 0 || height <= 0; }
};

// The box [lo, hi] (object space) projected by `mvp` onto a width x height target: the pixel
// bounds of its eight corners. False when a corner is behind the camera (no finite bounds).
bool projectBox(const glm::vec3& lo, const glm::vec3& hi, const glm::mat4& mvp, int width, int height, glm::vec2& min,
                glm::vec2& max);

// The pixels of a width x height target that the box [lo, hi] (object space) can cover
// under `mvp`, grown by `marginPx` and clamped to the target. If any corner is behind the
// camera the whole target is returned (the box's projection is then unbounded).
ScreenRect projectedBounds(const glm::vec3& lo, const glm::vec3& hi, const glm::mat4& mvp, int width, int height,
                           int marginPx = 2);

// The same region in a target 1/`factor` the size (rounded outward).
ScreenRect scaledDown(const ScreenRect& r, int factor);

// glScissor + GL_SCISSOR_TEST on; scissorOff() turns the test off again (passes leave it off).
void scissorTo(const ScreenRect& r);
void scissorOff();

}  // namespace marble
