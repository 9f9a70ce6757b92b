#pragma once
// The panel's material sections and "reset this section to the preset": which Material fields
// belong to which section. Header-only and GL-free so tests/viewer_sections_test.cpp can check
// that a reset touches its own section and nothing else.
#include "marble/scene/material.h"

namespace marble::viewer {

enum class MaterialSection { Pattern, Colour, Subsurface, Reflectance };

inline void resetSection(Material& m, const Material& preset, MaterialSection section) {
  switch (section) {
    case MaterialSection::Pattern:
      m.seed = preset.seed;
      m.resolution = preset.resolution;
      m.basis = preset.basis;
      m.mapping = preset.mapping;
      m.x_period = preset.x_period;
      m.y_period = preset.y_period;
      m.z_period = preset.z_period;
      m.turb_power = preset.turb_power;
      m.turb_size = preset.turb_size;
      m.pattern_scale = preset.pattern_scale;
      // vein model (issue 16)
      m.vein_model = preset.vein_model;
      m.vein_spacing = preset.vein_spacing;
      m.vein_width = preset.vein_width;
      m.vein_density = preset.vein_density;
      m.vein_normal = preset.vein_normal;
      m.vein_stretch = preset.vein_stretch;
      m.vein_warp = preset.vein_warp;
      m.vein_pinch = preset.vein_pinch;
      m.vein_softness = preset.vein_softness;
      m.grain_amount = preset.grain_amount;
      m.fragment_tint = preset.fragment_tint;
      break;
    case MaterialSection::Colour:
      m.base_color = preset.base_color;
      m.vein_color = preset.vein_color;
      m.vein2_color = preset.vein2_color;
      m.vein_sharpness = preset.vein_sharpness;
      m.vein2_amount = preset.vein2_amount;
      m.vein3_color = preset.vein3_color;  // vein model (issue 16)
      m.cloud_color = preset.cloud_color;
      m.cloud_amount = preset.cloud_amount;
      break;
    case MaterialSection::Subsurface:
      m.sigma_t = preset.sigma_t;
      m.k_sss = preset.k_sss;
      m.sigma_a_mm = preset.sigma_a_mm;
      m.sigma_s_mm = preset.sigma_s_mm;
      m.translucency = preset.translucency;
      break;
    case MaterialSection::Reflectance:  // with the comparison models' parameters
      m.k_schlick = preset.k_schlick;
      m.metalness = preset.metalness;
      m.ior = preset.ior;
      m.roughness = preset.roughness;
      m.order = preset.order;
      m.schlick_cos = preset.schlick_cos;
      m.shininess = preset.shininess;
      m.oren_nayar_sigma = preset.oren_nayar_sigma;
      break;
  }
}

}  // namespace marble::viewer
