#include "marble/bake/gltf_material.h"

#include <algorithm>
#include <cmath>

namespace marble {

GltfMaterialParams gltfMaterialFor(const Material& m, float mmPerUnit) {
  GltfMaterialParams p;
  p.roughness = std::clamp(m.roughness, 0.0f, 1.0f);
  p.metallic = std::clamp(m.metalness, 0.0f, 1.0f);
  p.ior = m.ior;
  p.metresPerUnit = mmPerUnit / 1000.0f;
  const glm::vec3 sigmaTrPerMetre = transportCoefficientMm(m) * 1000.0f;
  const float weakest = std::max(std::min({sigmaTrPerMetre.x, sigmaTrPerMetre.y, sigmaTrPerMetre.z}), 1e-6f);
  p.attenuationDistance = 1.0f / weakest;
  p.attenuationColor = glm::exp(-sigmaTrPerMetre * p.attenuationDistance);
  // Light inside a strongly scattering stone leaves by the front or the back with no preference
  // (the diffusion limit for a slab about one transport length thick); the volume's attenuation then
  // dims what comes through thick parts. marble's translucency scales the transmitted light.
  p.diffuseTransmission = std::min(1.0f, 0.5f * std::max(0.0f, m.translucency));
  return p;
}

}  // namespace marble
