#include "marble/scene/placement.h"

#include <algorithm>
#include <cmath>

#include "marble/scene/orbit.h"

namespace marble {

const std::vector<Placement>& lightPresets() {
  // Key-light heights a photographer would use: raised enough to model the form; the back
  // light low enough to shine through the thin parts towards the camera.
  static const std::vector<Placement> p = {
      {"front", 0.0f, 30.0f}, {"side", 90.0f, 25.0f}, {"back", 180.0f, 20.0f}, {"top", 0.0f, 90.0f}};
  return p;
}

const std::vector<Placement>& cameraPresets() {
  static const std::vector<Placement> p = {
      {"front", 0.0f, 10.0f}, {"side", 90.0f, 10.0f}, {"back", 180.0f, 10.0f}, {"top", 0.0f, 89.0f}};
  return p;
}

std::optional<Placement> findPreset(const std::vector<Placement>& presets, const std::string& name) {
  for (const auto& p : presets)
    if (name == p.name) return p;
  return std::nullopt;
}

float cameraAzimuthDeg(const Camera& camera) {
  return Orbit::fromPosition(camera.position, camera.target).yaw_deg;
}

namespace {
glm::vec3 direction(float azimuthDeg, float elevationDeg) {
  const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}
}  // namespace

void placeLight(Scene& scene, float azimuthDeg, float elevationDeg) {
  const float distance = glm::length(scene.light.position);
  glm::vec3 p = distance * direction(cameraAzimuthDeg(scene.camera) + azimuthDeg, elevationDeg);
  if (std::abs(elevationDeg) >= 90.0f) p.x = p.z = 0.0f;  // straight above: no rounding residue
  scene.light.position = p;
}

void placeCamera(Scene& scene, float azimuthDeg, float elevationDeg, float distance) {
  Camera& c = scene.camera;
  if (distance <= 0.0f) distance = glm::length(c.position - c.target);
  c.position = c.target + distance * direction(azimuthDeg, std::clamp(elevationDeg, -89.0f, 89.0f));
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace marble
