#pragma once
// The matrices a frame needs, derived once from the scene's camera and light.
// The normalized mesh fits in a sphere of radius sqrt(3) about the origin; near and far
// planes (and the light's frustum) are fitted to that sphere.
#include <glm/glm.hpp>

#include "marble/scene/scene.h"

namespace marble {

constexpr float kBoundingRadius = 1.7320508f;  // sqrt(3): the normalized mesh's bounding sphere

// The thickness view maps [0, kThicknessViewRange] scene units to black..white: the longest
// chord through the normalized mesh's bounding sphere.
constexpr float kThicknessViewRange = 2.0f * kBoundingRadius;

struct CameraMatrices {
  glm::mat4 view, proj, viewProj, invViewProj;
  glm::vec3 position;
  float near = 0.1f, far = 10.0f;
};

struct LightMatrices {
  glm::mat4 viewProj;
  glm::vec3 position;   // point light
  glm::vec3 direction;  // directional light: unit direction of travel
  bool directional = false;
  float near = 0.1f, far = 10.0f;  // range of stored distances
};

CameraMatrices cameraMatrices(const Camera& camera, float aspect);
LightMatrices lightMatrices(const Light& light);

}  // namespace marble
