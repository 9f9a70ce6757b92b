// The marble pattern for the geometry pass (paper §3.1). Include this (no #version here);
// it declares its uniforms (set from the
// material parameters' descriptions by marble::uploadMaterialUniforms, src/marble/render/material_uniforms.h)
// and provides:
//   vec3  marble_albedo(vec3 objectPos, vec3 objectNormal)         linear RGB albedo
//   float marble_pattern_value(vec3 objectPos, vec3 objectNormal)  sine pattern in [0,1], before colour
// objectPos: the normalized mesh's object-space position (mesh in [-1,1]^3);
// objectNormal: object-space normal (used by the triplanar mapping only).
// The functions themselves live in pattern_core.glsl, which the C++ reference compiles too.
#include "pattern_core.glsl"

uniform uint u_pat_seed;
uniform float u_pat_resolution;
// The basis and the mapping pick code paths: a program specialized for them (PAT_BASIS,
// PAT_MAPPING defined by the geometry pass) runs only its own (see gl/program_variants.h).
#ifdef PAT_BASIS
const int u_pat_basis = PAT_BASIS;
#else
uniform int u_pat_basis;
#endif
#ifdef PAT_MAPPING
const int u_pat_mapping = PAT_MAPPING;
#else
uniform int u_pat_mapping;
#endif
uniform float u_pat_x_period;
uniform float u_pat_y_period;
uniform float u_pat_z_period;
uniform float u_pat_turb_power;
uniform float u_pat_turb_size;
uniform float u_pat_scale;
uniform float u_pat_vein_sharpness;
uniform float u_pat_vein2_amount;
uniform vec3 u_pat_base_color;
uniform vec3 u_pat_vein_color;
uniform vec3 u_pat_vein2_color;
// The vein model (issue 16): a program constant when the pass specializes for it.
#ifdef PAT_VEIN_MODEL
const int u_pat_vein_model = PAT_VEIN_MODEL;
#else
uniform int u_pat_vein_model;
#endif
uniform vec3 u_pat_vein_spacing;
uniform vec3 u_pat_vein_width;
uniform vec3 u_pat_vein_density;
uniform vec3 u_pat_vein_normal;
uniform float u_pat_vein_stretch;
uniform float u_pat_vein_warp;
uniform float u_pat_vein_pinch;
uniform float u_pat_vein_softness;
uniform vec3 u_pat_vein3_color;
uniform vec3 u_pat_cloud_color;
uniform float u_pat_cloud_amount;
uniform float u_pat_grain_amount;
uniform float u_pat_fragment_tint;
uniform float u_pat_fragment_split;

PatParams marble_params() {
  PatParams P;
  P.seed = u_pat_seed;
  P.resolution = u_pat_resolution;
  P.basis = u_pat_basis;
  P.mapping = u_pat_mapping;
  P.period = vec3(u_pat_x_period, u_pat_y_period, u_pat_z_period);
  P.turbPower = u_pat_turb_power;
  P.turbSize = u_pat_turb_size;
  P.scale = u_pat_scale;
  P.sharpness = u_pat_vein_sharpness;
  P.vein2Amount = u_pat_vein2_amount;
  P.baseColor = u_pat_base_color;
  P.veinColor = u_pat_vein_color;
  P.vein2Color = u_pat_vein2_color;
  P.veinModel = u_pat_vein_model;
  P.veinSpacing = u_pat_vein_spacing;
  P.veinWidth = u_pat_vein_width;
  P.veinDensity = u_pat_vein_density;
  P.veinNormal = u_pat_vein_normal;
  P.veinStretch = u_pat_vein_stretch;
  P.veinWarp = u_pat_vein_warp;
  P.veinPinch = u_pat_vein_pinch;
  P.veinSoftness = u_pat_vein_softness;
  P.vein3Color = u_pat_vein3_color;
  P.cloudColor = u_pat_cloud_color;
  P.cloudAmount = u_pat_cloud_amount;
  P.grainAmount = u_pat_grain_amount;
  P.fragmentTint = u_pat_fragment_tint;
  P.fragmentSplit = u_pat_fragment_split;
  return P;
}

#ifdef PAT_TURBULENCE_GRID
// The turbulence baked at integer texels (src/marble/noise/turbulence_grid.h: with the value
// basis and power-of-two octaves, one linearly filtered fetch is the six octaves, exactly up
// to rounding). Defined by the passes with the grid's dimensions, 3 (solid) or 2; the program
// is specialized for it with PAT_MAPPING, so only the mapping's own lines run.
#if PAT_TURBULENCE_GRID == 3
layout(binding = UNIT_TURBULENCE_GRID) uniform sampler3D u_pat_turbulence_grid;
float pat_grid_turbulence3(vec3 q) { return texture(u_pat_turbulence_grid, (q + 0.5) / u_pat_resolution).r; }
#else
layout(binding = UNIT_TURBULENCE_GRID) uniform sampler2D u_pat_turbulence_grid;
// Texel i holds the value at q = i: its centre is at (i + 0.5) / W.
float pat_grid_turbulence2(vec2 q) { return texture(u_pat_turbulence_grid, (q + 0.5) / u_pat_resolution).r; }
float pat_grid_pattern2(PatParams P, vec2 q) { return pat_sine(pat_ramp2(P, q), pat_grid_turbulence2(q), P.turbPower); }
#endif

// pat_value_at (pattern_core.glsl) with the grid's turbulence.
float marble_paper_value(vec3 objectPos, vec3 objectNormal) {
  PatParams P = marble_params();
  vec3 q = pat_texel_pos(P, objectPos);
#if PAT_TURBULENCE_GRID == 3
  return pat_sine(pat_ramp3(P, q), pat_grid_turbulence3(q), P.turbPower);
#elif PAT_MAPPING == 0  // PAT_MAP_PLANAR
  return pat_grid_pattern2(P, pat_planar_texel(P, q));
#else
  return pat_triplanar_mix(pat_triplanar_weights(objectNormal), pat_grid_pattern2(P, vec2(q.z, q.y)),
                           pat_grid_pattern2(P, vec2(q.x, q.z)), pat_grid_pattern2(P, vec2(q.x, q.y)));
#endif
}
#else
float marble_paper_value(vec3 objectPos, vec3 objectNormal) {
  return pat_value_at(marble_params(), objectPos, objectNormal);
}
#endif

// The vein model's four turbulence samples at objectPos (pattern_core.glsl:
// pat_vein_sample_point): from the vein grid where the passes bound one (one fetch: texel i
// holds the four samples at texel point 2i, noise/turbulence_grid.h), else evaluated.
vec4 marble_vein_turbulence(PatParams P, vec3 objectPos) {
#if defined(PAT_TURBULENCE_GRID) && PAT_TURBULENCE_GRID == 3
  // Texel i of the (W/2)^3 grid holds texel point q = 2i; its centre is at (i + 0.5) / (W/2).
  return texture(u_pat_turbulence_grid, (pat_texel_pos(P, objectPos) + 1.0) / u_pat_resolution);
#else
  return vec4(pat_vein_turbulence(P, objectPos, 0), pat_vein_turbulence(P, objectPos, 1),
              pat_vein_turbulence(P, objectPos, 2), pat_vein_turbulence(P, objectPos, 3));
#endif
}

float marble_pattern_value(vec3 objectPos, vec3 objectNormal) {
  if (u_pat_vein_model == PAT_VEINS_PAPER) return marble_paper_value(objectPos, objectNormal);
  PatParams P = marble_params();
  vec4 t = marble_vein_turbulence(P, objectPos);
  return pat_vein_value(P, objectPos, t.x, t.y, t.z, t.w);
}

// The albedo seen through the polish along the refracted view ray (object space, unit) with
// attenuation k per object unit (pattern_core.glsl "veins seen through the polish"); the
// paper's model is a surface pattern and ignores them.
vec3 marble_albedo_seen(vec3 objectPos, vec3 objectNormal, vec3 ray, float k) {
  PatParams P = marble_params();
  if (u_pat_vein_model == PAT_VEINS_PAPER) return pat_color(P, marble_paper_value(objectPos, objectNormal));
  vec4 t = marble_vein_turbulence(P, objectPos);
  return pat_vein_shade_seen(P, objectPos, t.x, t.y, t.z, t.w, ray, k).xyz;
}

vec3 marble_albedo(vec3 objectPos, vec3 objectNormal) {
  PatParams P = marble_params();
  if (u_pat_vein_model == PAT_VEINS_PAPER) return pat_color(P, marble_paper_value(objectPos, objectNormal));
  vec4 t = marble_vein_turbulence(P, objectPos);
  return pat_vein_albedo(P, objectPos, t.x, t.y, t.z, t.w);
}
