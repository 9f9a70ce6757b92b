#pragma once
// How marble's material maps onto glTF 2.0's PBR metallic-roughness and the Khronos extensions
// (docs/export.md, "Mapping"). One place for the mapping: material.json and the .glb read it.
#include <glm/glm.hpp>

#include "marble/scene/material.h"

namespace marble {

struct GltfMaterialParams {
  float roughness = 0;           // = Material::roughness (both perceptual: GGX alpha = roughness^2)
  float metallic = 0;            // = Material::metalness
  float ior = 1.5f;              // KHR_materials_ior, = Material::ior
  float specular = 1;            // KHR_materials_specular: 1 keeps F0 = ((ior-1)/(ior+1))^2, as marble's GGX does
  // KHR_materials_volume: light that has travelled d metres keeps attenuationColor^(d / attenuationDistance).
  // From sigma_tr (transportCoefficientMm): distance = 1 / min over channels of sigma_tr, colour = exp(-sigma_tr * distance).
  glm::vec3 attenuationColor{1};
  float attenuationDistance = 0;  // metres
  float diffuseTransmission = 0;  // KHR_materials_diffuse_transmission factor
  float metresPerUnit = 0.1f;     // the normalized mesh's units in metres (mm_per_unit / 1000)
};

GltfMaterialParams gltfMaterialFor(const Material& m, float mmPerUnit);

}  // namespace marble
