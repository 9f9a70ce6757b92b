#pragma once
// Shared by the GL tests that read light off a rendered linear image at a world point.
#include <cstddef>

#include <glm/glm.hpp>

#include "marble/core/image.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble::test {

// Linear RGB of the 3x3 pixels around where world point p lands in `img` (row 0 the top),
// averaged: one pixel would be at the mercy of the rasterizer's rounding.
inline glm::vec3 linearRgbAround(const ImageRGBF& img, const Scene& s, glm::vec3 p) {
  const CameraMatrices cam = cameraMatrices(s.camera, 1.0f);
  const glm::vec4 clip = cam.viewProj * glm::vec4(p, 1.0f);
  const int cx = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * img.width);
  const int cy = static_cast<int>((0.5f - clip.y / clip.w * 0.5f) * img.height);
  glm::vec3 sum(0.0f);
  for (int y = cy - 1; y <= cy + 1; ++y)
    for (int x = cx - 1; x <= cx + 1; ++x) {
      const float* q = &img.pixels[(static_cast<size_t>(y) * img.width + x) * 3];
      sum += glm::vec3(q[0], q[1], q[2]);
    }
  return sum / 9.0f;
}

}  // namespace marble::test
