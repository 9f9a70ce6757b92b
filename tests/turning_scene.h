#pragma once
// What the interaction-detail tests (resolution scale, the light's maps) share: a `marble`-mode
// scene of a given size, and a position or a model turned about the vertical axis, the way a
// viewer's camera, light or turntable moves between frames.
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl_support.h"

namespace marble::test {

inline Scene marbleSceneOfSize(int size) {
  Scene s;
  s.render.width = s.render.height = size;
  s.render.mode = RenderMode::Marble;
  return s;
}

inline glm::vec3 turnedAboutY(glm::vec3 p, float degrees) {
  const float a = glm::radians(degrees);
  return {std::cos(a) * p.x + std::sin(a) * p.z, p.y, -std::sin(a) * p.x + std::cos(a) * p.z};
}

inline glm::mat4 turnedModel(float degrees) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
}

}  // namespace marble::test
