#include "marble/scene/orbit.h"

#include <algorithm>
#include <cmath>

namespace marble {

Orbit Orbit::fromPosition(const glm::vec3& position, const glm::vec3& target) {
  Orbit o;
  o.target = target;
  const glm::vec3 d = position - target;
  o.distance = std::clamp(glm::length(d), kMinDistance, kMaxDistance);
  const float len = glm::length(d);
  if (len > 1e-6f) {
    o.pitch_deg = std::clamp(glm::degrees(std::asin(std::clamp(d.y / len, -1.0f, 1.0f))), -89.0f, 89.0f);
    o.yaw_deg = glm::degrees(std::atan2(d.x, d.z));
  }
  return o;
}

glm::vec3 Orbit::position() const {
  const float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
  return target + distance * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

void Orbit::rotate(float dyaw, float dpitch) {
  yaw_deg = std::fmod(yaw_deg + dyaw, 360.0f);
  pitch_deg = std::clamp(pitch_deg + dpitch, -89.0f, 89.0f);
}

void Orbit::zoom(float steps) { distance = std::clamp(distance * std::pow(0.9f, steps), kMinDistance, kMaxDistance); }

void Orbit::pan(float dx, float dy) {
  const glm::vec3 forward = glm::normalize(target - position());
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, forward);
  target += (right * dx + up * dy) * distance;
}

}  // namespace marble
