#version 450 core
// Screen-space subsurface scattering (after Jimenez et al. 2015, "Separable Subsurface
// Scattering"): the light that entered the stone is spread over the surface by a diffusion
// profile, one axis per pass. The profile is Burley's normalized diffusion (Christensen &
// Burley 2015): R(r) = (exp(-r/d) + exp(-r/(3d))) / (8 pi d r), with d per channel in mm;
// its width on screen follows the millimetre scale and the surface's depth, and samples
// across a silhouette (a depth jump, or the background) are left out.
//
// Both passes run at half resolution by default: the profile is smooth, so a quarter of the
// pixels carry it (render.subsurface_resolution "full" runs them at full resolution). Blur
// texel h stands for the full-resolution pixel h * scale: its depth decides whether it is
// stone and which taps are on the same surface. Alpha is coverage (1 on stone, 0 on the
// background) between the passes and the view depth after them, for the post pass's
// depth-aware upsample (subsurface_common.glsl).
#include "subsurface_common.glsl"

layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_entering;  // full resolution (first pass) or half (second)
uniform int u_input_full;          // 1: u_entering is full resolution
uniform vec2 u_direction;          // (1,0) then (0,1)
uniform int u_taps;                // taps per side, 1..MAX_TAPS (as many as the reach spans on screen)
uniform float u_step_mm;           // spacing of the taps, mm (u_reach_mm / u_taps)
uniform vec3 u_weights[10];        // burley_1d(i * step) for i = 0..u_taps, computed on the CPU

const int MAX_TAPS = 9;            // kMaxTaps in subsurface_blur_pass.cpp

void main() {
  ivec2 h = ivec2(gl_FragCoord.xy);
  float z = representative_depth(h);
  if (z >= 1.0) {
    o_color = vec4(0.0);  // background: no light, no coverage
    return;
  }
  float depth = view_depth(z);
  float reach_mm = u_reach_mm;
  // Taps are read with bilinear filtering at fractional positions (a profile narrower than a
  // texel still blurs a little, as it should), in the input's own texels. Alpha is coverage
  // (the background is cleared to 0), so a tap half on the background counts half.
  int k = u_input_full == 1 ? u_scale : 1;  // input pixels per blur texel
  vec2 input_size = vec2(textureSize(u_entering, 0));
  vec2 centre = vec2(h * k) + 0.5;  // the representative pixel, in input texels
  float input_px_per_mm = u_pixels_per_mm_at_unit_depth / (float(u_scale / k) * depth);
  vec3 sum = vec3(0.0), weight = vec3(0.0);
  for (int i = -u_taps; i <= u_taps; ++i) {
    vec2 p = centre + u_direction * (float(i) * u_step_mm * input_px_per_mm);
    // The tap's depth: that of the full-resolution pixel its input texel stands for.
    float zi = texelFetch(u_depth, ivec2(floor(p)) * (u_scale / k), 0).r;
    if (zi >= 1.0) continue;
    // Across a silhouette: the neighbour is more than the reach away in depth.
    if (abs(view_depth(zi) - depth) * u_mm_per_unit > reach_mm) continue;
    vec3 w = u_weights[abs(i)];
    vec4 e = texture(u_entering, p / input_size);
    sum += w * e.rgb;  // premultiplied by coverage
    weight += w * e.a;
  }
  // Alpha: coverage (1) between the passes; after the second, the texel's view depth, which
  // the post pass's depth-aware upsample compares (0 = background).
  o_color = vec4(sum / max(weight, vec3(1e-8)), u_input_full == 1 ? 1.0 : depth);
}
