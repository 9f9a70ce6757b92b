#version 450 core
// Last pass: from the linear HDR lighting result to the display. For `marble`: exposure,
// the Khronos PBR Neutral tone map, then the sRGB transfer function. The paper's modes and the
// buffer views were never colour-managed: they pass through as they are.
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_hdr;
layout(binding = 1) uniform sampler2D u_depth;
uniform int u_tone_map;
uniform int u_paint_background;   // 0 for views that are not of the camera's G-buffer
uniform float u_exposure_scale;   // 2^exposure
uniform vec3 u_background;

// Khronos PBR Neutral tone mapper (Khronos 3D Commerce, 2024): keeps base colours within
// [0, 0.8] as they are, compresses highlights, desaturates the brightest toward white.
vec3 pbr_neutral(vec3 color) {
  const float start = 0.8 - 0.04;
  const float desaturation = 0.15;
  float x = min(color.r, min(color.g, color.b));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  color -= offset;
  float peak = max(color.r, max(color.g, color.b));
  if (peak < start) return color;
  const float d = 1.0 - start;
  float new_peak = 1.0 - d * d / (peak + d - start);
  color *= new_peak / peak;
  float g = 1.0 - 1.0 / (desaturation * (peak - new_peak) + 1.0);
  return mix(color, vec3(new_peak), g);
}

// sRGB OETF (IEC 61966-2-1).
vec3 srgb_encode(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
  vec3 c = texture(u_hdr, v_uv).rgb;
  if (u_tone_map == 1) c = srgb_encode(pbr_neutral(c * u_exposure_scale));
  // The background colour is a display colour: it is not tone mapped.
  if (u_paint_background == 1 && texture(u_depth, v_uv).r >= 1.0) c = u_background;
  o_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
