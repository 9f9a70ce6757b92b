// From linear light to the display, shared by the post pass and the stage pass (the two must
// agree, so the stage meets the object without a seam).

// FXAA's luma (fxaa.frag.glsl): Rec. 601 weights on the display-encoded values, computed
// here once per pixel instead of nine or more times per pixel there.
float fxaa_luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

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
