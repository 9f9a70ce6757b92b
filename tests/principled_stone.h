#pragma once
// The white stone of issue 15 in Blender's Principled terms, the one the Cycles references use:
// subsurface radius (17, 12, 8) mm as Cycles' RANDOM_WALK reads it, IOR 1.5, roughness 0.15, a
// plain colour (veins the same as the ground, so no pattern shows). Shared by the tests that
// check marble's light against closed forms or walks computed for exactly this stone.
#include <glm/glm.hpp>

#include "marble/scene/material.h"
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

}  // namespace marble::test
