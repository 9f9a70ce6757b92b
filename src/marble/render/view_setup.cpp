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
  m.bounceViewProj = m.viewProj;
  return m;
}

void fitBounceMap(LightMatrices& m, const Light& light, glm::vec3 lo, glm::vec3 hi, const glm::mat4& model) {
  const glm::vec3 toLight = glm::normalize(light.position);
  const glm::vec3 up = std::abs(toLight.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::mat4 view = glm::lookAt(m.directional ? m.position : light.position, glm::vec3(0), up);
  // The box's corners on the view plane: x, y (directional) or x / -z, y / -z (point).
  glm::vec2 a(1e30f), b(-1e30f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    const glm::vec4 v = view * model * glm::vec4(c, 1.0f);
    if (!m.directional && v.z > -1e-3f) return;  // a light inside the box: keep the sphere's frustum
    const glm::vec2 p = m.directional ? glm::vec2(v) : glm::vec2(v) / -v.z;
    a = glm::min(a, p);
    b = glm::max(b, p);
  }
  // Square, centred on the box's projection, 2 % wider (the rasterizer's edge texels).
  const glm::vec2 centre = 0.5f * (a + b);
  const float half = 0.51f * std::max(b.x - a.x, b.y - a.y);
  if (m.directional) {
    m.bounceViewProj = glm::ortho(centre.x - half, centre.x + half, centre.y - half, centre.y + half, 0.5f,
                                  2.0f * kBoundingRadius + 1.5f) * view;
  } else {
    const float n = m.near;
    m.bounceViewProj =
        glm::frustum((centre.x - half) * n, (centre.x + half) * n, (centre.y - half) * n, (centre.y + half) * n, n, m.far) * view;
  }
}

}  // namespace marble
