#pragma once
// The marble material: the vein pattern (paper §3.1), its colours, and how light meets it
// (paper §3.2 subsurface, §3.3 Fresnel-Schlick; the physically based `marble` mode's
// scattering and gloss). The fields are grouped by what consumes them, one struct per group,
// so a pass's cache compares exactly the groups it reads (Material::pattern() == ...).
// Every field is described once, in src/marble/scene/material_params.cpp (key, range, unit,
// tooltip, the modes and passes that read it, its shader uniform); JSON, `--set`, the panel,
// the uniforms and docs/materials.md's tables all come from that description.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace marble {

// Enum values are also the GLSL's (PAT_BASIS_*, PAT_MAP_*, the lighting shader's order and
// cosine switches): the uniforms carry the enum's integer. Names: material_params.cpp.
enum class NoiseBasis { Value, Perlin };          // key "basis": "value" (the paper's) | "perlin"
enum class PatternMapping { Planar, Triplanar, Solid };  // key "mapping": "planar" | "triplanar" | "solid"
enum class ShadingOrder { SubsurfaceFirst, ReflectanceFirst };  // key "order": "sss-first" | "schlick-first"
enum class SchlickCosine { HdotV, HdotN };        // key "schlick_cos": "hv" | "hn"
// key "schlick_blend": how the Schlick term meets the colour: "opacity" (the paper's text, §3.3:
// k_schlick is the term's opacity, mix(colour, F, k)) | "program" (the paper's own program,
// judgyknowitall/marble-renderable lightPass.fs.glsl: colour - k (1 - F)).
enum class SchlickBlend { Opacity, Program };
// key "vein_model": "paper" (the paper's |sin(ramp + turbulence)|) | "network" (crack networks,
// issue 16) | "breccia" (angular fragments in a matrix of crack veins).
enum class VeinModel { Paper, Network, Breccia };
// Key "scattering": how the `marble` mode's stone scatters is given: "coefficients" (sigma_a_mm,
// sigma_s_mm) or "radius" (Blender's Principled BSDF: base_color, subsurface_radius_mm, ior).
enum class ScatteringForm { Coefficients, Radius };

// The vein pattern (paper §3.1): read wherever the marble's colour is evaluated.
struct PatternParams {
  uint32_t seed = 1;
  int resolution = 256;
  NoiseBasis basis = NoiseBasis::Value;
  PatternMapping mapping = PatternMapping::Solid;
  float x_period = 5.0f;
  float y_period = 10.0f;
  float z_period = 0.0f;
  float turb_power = 5.0f;
  float turb_size = 32.0f;
  float pattern_scale = 1.0f;
  bool operator==(const PatternParams&) const = default;
};

// The stone between veins: the colour ramp's end (read with the pattern), `floor`'s flat colour,
// and in `marble` also read by the lighting pass (the bounce's emitters, shaders/bounce_upsample.glsl;
// the radius form's albedo): a group of its own, so that the vein colours below do not re-run it.
struct BaseColourParams {
  glm::vec3 base_color{0.93f, 0.89f, 0.80f};
  bool operator==(const BaseColourParams&) const = default;
};

// The rest of the colour ramp over the pattern: read with it.
struct ColourParams {
  glm::vec3 vein_color{0.52f, 0.3f, 0.09f};
  glm::vec3 vein2_color{0.74f, 0.56f, 0.3f};
  float vein_sharpness = 1.0f;
  float vein2_amount = 0.0f;
  bool operator==(const ColourParams&) const = default;
};

// The vein model (issue 16; docs/materials.md "Vein model"): read with the pattern when
// vein_model != paper, which always uses the solid mapping; the turbulence above warps the
// veins. Per-family triples are (dominant, secondary, hairline); colours are vein_color,
// vein2_color, vein3_color.
struct VeinModelParams {
  VeinModel vein_model = VeinModel::Paper;
  glm::vec3 vein_spacing{0.9f, 0.35f, 0.12f};
  glm::vec3 vein_width{0.03f, 0.012f, 0.004f};
  glm::vec3 vein_density{0.7f, 0.5f, 0.4f};
  glm::vec3 vein_normal{-0.5f, 1.0f, 0.2f};  // normalized on use
  float vein_stretch = 2.5f;
  float vein_warp = 0.25f;
  float vein_pinch = 0.7f;
  float vein_softness = 0.4f;
  glm::vec3 vein3_color{0.6f, 0.6f, 0.62f};
  glm::vec3 cloud_color{0.7f, 0.71f, 0.73f};
  float cloud_amount = 0.5f;
  float grain_amount = 0.06f;
  float fragment_tint = 0.0f;
  float fragment_split = 0.0f;
  bool operator==(const VeinModelParams&) const = default;
};

// The paper's models (§3.2 subsurface, §3.3 Schlick, §4 their order): the `paper`,
// `subsurface` and `reflectance` modes' lighting pass.
struct PaperModelParams {
  glm::vec3 sigma_t{0.6f, 0.9f, 1.3f};
  float k_sss = 1.0f;
  float k_schlick = 0.5f;
  float metalness = 0.0f;
  ShadingOrder order = ShadingOrder::SubsurfaceFirst;
  SchlickCosine schlick_cos = SchlickCosine::HdotN;  // the paper's H.N
  SchlickBlend schlick_blend = SchlickBlend::Opacity;
  bool operator==(const PaperModelParams&) const = default;
};

// The comparison models' lighting pass (`phong`, `oren-nayar`).
struct ComparisonParams {
  float shininess = 32.0f;
  float oren_nayar_sigma = 0.3f;
  bool operator==(const ComparisonParams&) const = default;
};

// Light entering and crossing the stone (`marble` mode: its lighting pass and blur).
// Jensen et al. 2001, "A Practical Model for Subsurface Light Transport", Table 1 (marble), per mm.
// The same stone in Blender's terms (issue 15; src/marble/scene/material_scattering.h): in the
// radius form base_color is the subsurface albedo and subsurface_radius_mm the mean free path per
// channel in mm, exactly Cycles' RANDOM_WALK Subsurface Radius (mm_per_unit turns it into scene
// units); sigma_a_mm and sigma_s_mm are then derived by Cycles' own conversion
// (resolveScattering). Giving subsurface_radius_mm selects the radius form, giving sigma_a_mm or
// sigma_s_mm the coefficient form. Default radius: Jensen's marble above, as Cycles would need it
// for albedo 0.83, 0.79, 0.75 at ior 1.55 (the same extinction sigma_a + sigma_s).
struct ScatteringParams {
  glm::vec3 sigma_a_mm{0.0021f, 0.0041f, 0.0071f};
  glm::vec3 sigma_s_mm{2.19f, 2.62f, 3.00f};
  float ior = 1.55f;  // also the reflection's F0 in the post pass
  float translucency = 1.0f;
  ScatteringForm scattering = ScatteringForm::Coefficients;
  glm::vec3 subsurface_radius_mm{9.73f, 6.3f, 4.1f};
  bool operator==(const ScatteringParams&) const = default;
};

// What the surface reflects (`marble` mode: the post pass alone).
struct GlossParams {
  float roughness = 0.12f;
  bool operator==(const GlossParams&) const = default;
};

struct Material : PatternParams, BaseColourParams, ColourParams, VeinModelParams, PaperModelParams, ComparisonParams, ScatteringParams,
                  GlossParams {
  std::string name = "paper";
  // The defaults are presets/paper.json, the paper's Figure 10 (MaterialIoTest.DefaultIsThePaperPreset).
  std::string description = "The paper's default (its Figure 10): cream stone with ochre-brown veins";

  bool operator==(const Material&) const = default;
};

// The direction the dominant veins' planes face (vein_normal normalized; +x for a zero vector,
// which files and `--set` refuse): what the pattern's evaluation reads on the CPU and the GPU.
inline glm::vec3 veinDirection(const Material& m) {
  const float len = glm::length(m.vein_normal);
  return len > 0.0f ? m.vein_normal / len : glm::vec3(1.0f, 0.0f, 0.0f);
}

// The effective transport coefficient sigma_tr = sqrt(3 sigma_a (sigma_a + sigma_s')) per channel,
// per mm (Jensen et al. 2001, eq. 5): light diffusing through the stone falls off as exp(-sigma_tr s).
// Read by the `marble` mode's transmission and by the glTF export's attenuation.
inline glm::vec3 transportCoefficientMm(const Material& m) {
  return glm::sqrt(3.0f * m.sigma_a_mm * (m.sigma_a_mm + m.sigma_s_mm));
}

}  // namespace marble
