#pragma once
// The white stone of issue 15 in Blender's Principled terms, the one the Cycles references use:
// subsurface radius (17, 12, 8) mm as Cycles' RANDOM_WALK reads it, IOR 1.5, roughness 0.15, a
// plain colour (veins the same as the ground, so no pattern shows). Shared by the tests that
// check marble's light against closed forms or walks computed for exactly this stone.
#include <glm/glm.hpp>

#include <string>

#include "marble/scene/material.h"
#include "marble/scene/scene.h"
#include "marble/scene/material_scattering.h"

namespace marble::test {

inline Material principledStone(const glm::vec3& colour = glm::vec3(0.87f, 0.85f, 0.8f)) {
  Material m;
  m.base_color = m.vein_color = m.vein2_color = colour;
  m.subsurface_radius_mm = {17.0f, 12.0f, 8.0f};
  m.scattering = ScatteringForm::Radius;
  m.ior = 1.5f;
  m.roughness = 0.15f;
  resolveScattering(m);
  return m;
}

// A test mesh lit from straight behind (a directional light along +z) and seen head-on from 6
// units in `marble` mode without environment light: the set-up of the transmission tests, which
// read what comes through the stone toward the camera.
inline Scene backLitScene(const std::string& mesh, float mmPerUnit, int size) {
  Scene s;
  s.mesh = mesh;
  s.mm_per_unit = mmPerUnit;
  s.render.width = s.render.height = size;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  s.camera.position = {0, 0, 6};
  s.camera.target = {0, 0, 0};
  s.camera.fov_y_deg = 22;
  s.light.type = LightType::Directional;
  s.light.position = {0, 0, -1};  // from behind: the light travels along +z
  s.light.intensity = 1.0f;
  s.material = principledStone();
  return s;
}

}  // namespace marble::test
