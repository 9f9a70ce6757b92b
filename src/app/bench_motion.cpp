#include "bench_motion.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "marble/core/error.h"
#include "marble/scene/orbit.h"

namespace marble {

namespace {

// A few degrees per frame: what an orbiting hand does at 30-60 frames per second, and small
// enough that the object stays in view over any number of frames.
constexpr float kCameraDegPerFrame = 2.0f;
constexpr float kLightDegPerFrame = 3.0f;

struct Named {
  BenchMotion motion;
  const char* name;
};
constexpr Named kMotions[] = {{BenchMotion::None, "none"},
                              {BenchMotion::Camera, "camera"},
                              {BenchMotion::Light, "light"},
                              {BenchMotion::Both, "both"},
                              {BenchMotion::Params, "params"},
                              {BenchMotion::Scattering, "scattering"},
                              {BenchMotion::Pattern, "pattern"}};

void orbitCamera(Camera& camera, int frame) {
  Orbit orbit = Orbit::fromPosition(camera.position, camera.target);
  orbit.rotate(kCameraDegPerFrame * static_cast<float>(frame), 0.0f);
  camera.position = orbit.position();
}

void turnLight(Light& light, int frame) {
  // About +Y through the origin (the normalized mesh's centre); for a directional light
  // `position` is the direction it comes from, and the same rotation applies.
  const float angle = glm::radians(kLightDegPerFrame * static_cast<float>(frame));
  light.position = glm::vec3(glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0, 1, 0)) * glm::vec4(light.position, 1.0f));
}

// sin of distinct integers never repeats, so every frame sees new values.
float wave(int frame) { return std::sin(0.7f * static_cast<float>(frame)); }

void moveGloss(Material& m, int frame) {
  // Lighting-only parameters, so the G-buffer stays valid: the "re-shade from the G-buffer"
  // case. k_schlick is what the paper's mode reads, roughness what `marble` reads (in its
  // post pass: the light entering the stone does not depend on it).
  m.k_schlick = std::clamp(m.k_schlick + 0.3f * wave(frame), 0.0f, 1.0f);
  m.roughness = std::clamp(m.roughness * (1.0f + 0.5f * wave(frame)), 0.02f, 1.0f);
}

void moveScattering(Material& m, int frame) {
  // How far light spreads in the stone: the light entering it and its blur change.
  m.sigma_s_mm *= 1.0f + 0.3f * wave(frame);
}

void movePattern(Material& m, int frame) {
  // What bends the veins of the material's own model, so every pixel's pattern changes: the
  // paper's |sin| reads turb_power, the network and breccia models the domain warp (they never
  // read turb_power; moving it there would measure a pattern that does not change).
  if (m.vein_model == VeinModel::Paper)
    m.turb_power = std::max(0.0f, m.turb_power * (1.0f + 0.3f * wave(frame)));
  else
    m.vein_warp = std::max(0.0f, m.vein_warp * (1.0f + 0.3f * wave(frame)));
}

}  // namespace

BenchMotion parseBenchMotion(const std::string& name) {
  for (const auto& m : kMotions)
    if (name == m.name) return m.motion;
  throw InputError("--motion", "", "expected one of none, camera, light, both, params, scattering, pattern, got \"" + name + "\"");
}

const char* benchMotionName(BenchMotion motion) {
  for (const auto& m : kMotions)
    if (m.motion == motion) return m.name;
  return "?";
}

Scene sceneAtFrame(const Scene& base, BenchMotion motion, int frame) {
  Scene s = base;
  if (motion == BenchMotion::Camera || motion == BenchMotion::Both) orbitCamera(s.camera, frame);
  if (motion == BenchMotion::Light || motion == BenchMotion::Both) turnLight(s.light, frame);
  if (motion == BenchMotion::Params) moveGloss(s.material, frame);
  if (motion == BenchMotion::Scattering) moveScattering(s.material, frame);
  if (motion == BenchMotion::Pattern) movePattern(s.material, frame);
  return s;
}

}  // namespace marble
