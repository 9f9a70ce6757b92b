#include "marble/render/screen_rect.h"

#include <algorithm>
#include <cmath>
#include <epoxy/gl.h>

namespace marble {

bool projectBox(const glm::vec3& lo, const glm::vec3& hi, const glm::mat4& mvp, int width, int height, glm::vec2& min,
                glm::vec2& max) {
  min = glm::vec2(1e30f);
  max = glm::vec2(-1e30f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    const glm::vec4 clip = mvp * glm::vec4(corner, 1.0f);
    if (!(clip.w > 1e-6f)) return false;  // behind (or on) the eye plane: no finite box
    const glm::vec2 p = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width, height);
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  return true;
}

ScreenRect projectedBounds(const glm::vec3& lo, const glm::vec3& hi, const glm::mat4& mvp, int width, int height,
                           int marginPx) {
  glm::vec2 lower, upper;
  if (!projectBox(lo, hi, mvp, width, height, lower, upper)) return {0, 0, width, height};
  const float minX = lower.x, minY = lower.y, maxX = upper.x, maxY = upper.y;
  const int x0 = std::clamp(static_cast<int>(std::floor(minX)) - marginPx, 0, width);
  const int y0 = std::clamp(static_cast<int>(std::floor(minY)) - marginPx, 0, height);
  const int x1 = std::clamp(static_cast<int>(std::ceil(maxX)) + marginPx, 0, width);
  const int y1 = std::clamp(static_cast<int>(std::ceil(maxY)) + marginPx, 0, height);
  return {x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0)};
}

ScreenRect scaledDown(const ScreenRect& r, int factor) {
  const int x0 = r.x / factor, y0 = r.y / factor;
  const int x1 = (r.x + r.width + factor - 1) / factor, y1 = (r.y + r.height + factor - 1) / factor;
  return {x0, y0, x1 - x0, y1 - y0};
}

void scissorTo(const ScreenRect& r) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(r.x, r.y, r.width, r.height);
}

void scissorOff() { glDisable(GL_SCISSOR_TEST); }

}  // namespace marble
