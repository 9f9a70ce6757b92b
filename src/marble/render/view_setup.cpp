#include "marble/render/view_setup.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace marble {

CameraMatrices cameraMatrices(const Camera& camera, float aspect) {
  CameraMatrices m;
  m.position = camera.position;
  const float dist = glm::length(camera.position);
  m.near = std::max(0.01f, dist - kBoundingRadius - 0.1f);
  m.far = dist + kBoundingRadius + 0.1f;
  m.view = glm::lookAt(camera.position, camera.target, camera.up);
  m.proj = glm::perspective(glm::radians(camera.fov_y_deg), aspect, m.near, m.far);
  m.viewProj = m.proj * m.view;
  m.invViewProj = glm::inverse(m.viewProj);
  return m;
}

LightMatrices lightMatrices(const Light& light) {
  LightMatrices m;
  const glm::vec3 toLight = glm::normalize(light.position);
  const glm::vec3 up = std::abs(toLight.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const float margin = 0.05f;
  if (light.type == LightType::Directional) {
    m.directional = true;
    m.direction = -toLight;
    const glm::vec3 eye = toLight * (kBoundingRadius + 1.0f);
    const float r = kBoundingRadius + margin;
    m.viewProj = glm::ortho(-r, r, -r, r, 0.5f, 2.0f * kBoundingRadius + 1.5f) * glm::lookAt(eye, glm::vec3(0), up);
    m.near = -kBoundingRadius;
    m.far = kBoundingRadius;
    m.position = eye;
  } else {
    m.position = light.position;
    const float dist = glm::length(light.position);
    // A light inside the bounding sphere still gets a usable (wide) frustum.
    const float halfAngle = dist > kBoundingRadius + margin ? std::asin((kBoundingRadius + margin) / dist) : glm::radians(75.0f);
    m.near = std::max(0.01f, dist - kBoundingRadius - margin);
    m.far = dist + kBoundingRadius + margin;
    m.viewProj = glm::perspective(2.0f * halfAngle, 1.0f, m.near, m.far) * glm::lookAt(light.position, glm::vec3(0), up);
  }
  return m;
}

}  // namespace marble
