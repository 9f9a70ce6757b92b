#pragma once
// The marble material: the vein pattern (paper §3.1), its colours, and how light meets it
// (paper §3.2 subsurface, §3.3 Fresnel-Schlick). Every field has a flat key in preset
// files and on the command line (`--set key=value`); the keys are listed in
// docs/materials.md and by materialKeys().
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace marble {

enum class NoiseBasis { Value, Perlin };          // key "basis": "value" (the paper's) | "perlin"
enum class PatternMapping { Planar, Triplanar, Solid };  // key "mapping": "planar" | "triplanar" | "solid"
enum class ShadingOrder { SubsurfaceFirst, ReflectanceFirst };  // key "order": "sss-first" | "schlick-first"
enum class SchlickCosine { HdotV, HdotN };        // key "schlick_cos": "hv" | "hn"
// key "vein_model": "paper" (the paper's |sin(ramp + turbulence)|) | "network" (crack networks,
// issue 16) | "breccia" (angular fragments in a matrix of crack veins).
enum class VeinModel { Paper, Network, Breccia };

struct Material {
  std::string name = "paper";
  std::string description = "The paper's default: cream stone with ochre veins";

  // --- pattern (paper §3.1) ---
  uint32_t seed = 1;             // "seed": lattice of white noise
  int resolution = 256;          // "resolution": W = H, texels of the paper's texture / lattice cells per 2 units
  NoiseBasis basis = NoiseBasis::Value;  // "basis"
  PatternMapping mapping = PatternMapping::Solid;  // "mapping"
  float x_period = 5.0f;         // "x_period": vein repetitions along x over the texture
  float y_period = 10.0f;        // "y_period": along y (the texture's t)
  float z_period = 0.0f;         // "z_period": along z (solid mapping only)
  float turb_power = 5.0f;       // "turb_power": 0 gives a plain sine
  float turb_size = 32.0f;       // "turb_size": first octave size in texels, halves each octave
  float pattern_scale = 1.0f;    // "pattern_scale": object units per texture width / 2

  // --- colour ---
  glm::vec3 base_color{0.93f, 0.89f, 0.80f};   // "base_color": linear RGB of the stone
  glm::vec3 vein_color{0.55f, 0.38f, 0.16f};   // "vein_color": main veins
  glm::vec3 vein2_color{0.75f, 0.62f, 0.42f};  // "vein2_color": secondary veins (ramp middle)
  float vein_sharpness = 1.0f;   // "vein_sharpness": exponent on the sine (1 = the paper)
  float vein2_amount = 0.0f;     // "vein2_amount": 0 = two-colour ramp (the paper)

  // --- vein model (issue 16; docs/materials.md "Vein model"). Read when vein_model != paper,
  // which always uses the solid mapping; the turbulence above warps the veins. Per-family
  // triples are (dominant, secondary, hairline); colours are vein_color, vein2_color, vein3_color.
  VeinModel vein_model = VeinModel::Paper;          // "vein_model"
  glm::vec3 vein_spacing{0.9f, 0.35f, 0.12f};      // "vein_spacing": mean distance between cracks, object units
  glm::vec3 vein_width{0.03f, 0.012f, 0.004f};     // "vein_width": full width of a vein, object units
  glm::vec3 vein_density{0.7f, 0.5f, 0.4f};        // "vein_density": fraction of cracks filled, [0,1]
  glm::vec3 vein_normal{-0.5f, 1.0f, 0.2f};     // "vein_normal": normal of the planes the dominant veins lie in (normalized on use)
  float vein_stretch = 2.5f;     // "vein_stretch": dominant cells this many times thinner across those planes
  float vein_warp = 0.25f;       // "vein_warp": how far the turbulence bends the cracks, object units
  float vein_pinch = 0.7f;       // "vein_pinch": width swell/pinch along a vein; 1 lets veins fade out
  float vein_softness = 0.4f;    // "vein_softness": edge blur relative to the width
  glm::vec3 vein3_color{0.6f, 0.6f, 0.62f};   // "vein3_color": hairline veins
  glm::vec3 cloud_color{0.7f, 0.71f, 0.73f};  // "cloud_color": the ground's clouds (nuvolato) and fragment tints
  float cloud_amount = 0.5f;     // "cloud_amount": [0,1]
  float grain_amount = 0.06f;    // "grain_amount": [0,1] contrast of the calcite grain
  float fragment_tint = 0.0f;    // "fragment_tint": breccia, [0,1] how much fragments differ in colour

  // --- subsurface (paper §3.2, GPU Gems 1 ch. 16) ---
  glm::vec3 sigma_t{0.6f, 0.9f, 1.3f};  // "sigma_t": extinction per scene unit, per channel
  float k_sss = 1.0f;            // "k_sss": strength of the subsurface term

  // --- reflectance (paper §3.3) ---
  float k_schlick = 0.5f;        // "k_schlick": opacity of the Schlick reflectance
  float metalness = 0.0f;        // "metalness": F0 = mix(0.04, diffuse, metalness)
  ShadingOrder order = ShadingOrder::SubsurfaceFirst;  // "order"
  SchlickCosine schlick_cos = SchlickCosine::HdotV;    // "schlick_cos"

  // --- comparison models ---
  float shininess = 32.0f;       // "shininess": Phong exponent
  float oren_nayar_sigma = 0.3f; // "oren_nayar_sigma": roughness (radians) of Oren-Nayar

  // --- physically based marble (render mode `marble`, issue 5) ---
  // Jensen et al. 2001, "A Practical Model for Subsurface Light Transport", Table 1 (marble), per mm.
  glm::vec3 sigma_a_mm{0.0021f, 0.0041f, 0.0071f};  // "sigma_a_mm": absorption coefficient, 1/mm
  glm::vec3 sigma_s_mm{2.19f, 2.62f, 3.00f};        // "sigma_s_mm": reduced scattering coefficient, 1/mm
  float ior = 1.55f;             // "ior": calcite is 1.486-1.658 (F0 about 0.04-0.06)
  float roughness = 0.12f;       // "roughness": perceptual; GGX alpha = roughness^2. Polished 0.05-0.15, honed 0.4-0.6
  float translucency = 1.0f;     // "translucency": scales light transmitted through thin parts (1 = physical)

  bool operator==(const Material&) const = default;
};

// The effective transport coefficient sigma_tr = sqrt(3 sigma_a (sigma_a + sigma_s')) per channel,
// per mm (Jensen et al. 2001, eq. 5): light diffusing through the stone falls off as exp(-sigma_tr s).
// Read by the `marble` mode's transmission and by the glTF export's attenuation.
inline glm::vec3 transportCoefficientMm(const Material& m) {
  return glm::sqrt(3.0f * m.sigma_a_mm * (m.sigma_a_mm + m.sigma_s_mm));
}

}  // namespace marble
