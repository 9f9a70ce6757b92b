#pragma once
// Spherical coordinates about a target, for the viewer's orbit camera and for moving the
// light around the object. Pure math, no GL: unit-tested on its own.
#include <glm/glm.hpp>

namespace marble {

struct Orbit {
  float yaw_deg = 0.0f;     // around +Y, 0 = looking from +Z
  float pitch_deg = 0.0f;   // above the XZ plane, clamped to (-89, 89)
  float distance = 4.0f;    // clamped to [kMinDistance, kMaxDistance]
  glm::vec3 target{0.0f};

  static constexpr float kMinDistance = 0.2f;
  static constexpr float kMaxDistance = 100.0f;

  static Orbit fromPosition(const glm::vec3& position, const glm::vec3& target = glm::vec3(0.0f));
  glm::vec3 position() const;
  void rotate(float dyaw_deg, float dpitch_deg);
  void zoom(float wheelSteps);  // each step moves 10% closer (positive) or farther (negative)
  void pan(float dx, float dy); // in units of the distance, along the view's right and up
};

}  // namespace marble
