#version 450 core
// Screen-space subsurface scattering (after Jimenez et al. 2015, "Separable Subsurface
// Scattering"): the light that entered the stone is spread over the surface by a diffusion
// profile, one axis per pass. The profile is Burley's normalized diffusion (Christensen &
// Burley 2015): R(r) = (exp(-r/d) + exp(-r/(3d))) / (8 pi d r), with d per channel in mm;
// its width on screen follows the millimetre scale and the surface's depth, and samples
// across a silhouette (a depth jump, or the background) are left out.
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
layout(binding = 0) uniform sampler2D u_entering;  // diffuse irradiance / PI (or last pass's blur)
layout(binding = 1) uniform sampler2D u_depth;
layout(binding = 2) uniform sampler2D u_albedo;
layout(binding = 3) uniform sampler2D u_reflected;  // specular, added in the final pass
uniform vec2 u_direction;          // (1,0) then (0,1)
uniform vec3 u_d_mm;               // Burley's d per channel, mm
uniform float u_step_mm;           // spacing of the taps, mm (2 * widest d / TAPS)
uniform vec3 u_weights[10];        // burley_1d(i * step) for i = 0..TAPS, computed once on the CPU
uniform float u_pixels_per_mm_at_unit_depth;  // projection scale: px per mm at view distance 1 unit
uniform vec2 u_near_far;
uniform float u_mm_per_unit;
uniform int u_final;               // second pass: multiply by albedo and add the reflected light

const int TAPS = 9;                // per side; kTaps in subsurface_blur_pass.cpp

float view_depth(float z) {  // linear distance along the view axis, in scene units
  float n = u_near_far.x, f = u_near_far.y;
  return 2.0 * n * f / (f + n - (2.0 * z - 1.0) * (f - n));
}


void main() {
  float z = texture(u_depth, v_uv).r;
  vec3 centre = texture(u_entering, v_uv).rgb;
  if (z >= 1.0) {
    o_color = vec4(u_final == 1 ? texture(u_reflected, v_uv).rgb : centre, 1.0);
    return;
  }
  float depth = view_depth(z);
  float step_mm = u_step_mm;
  float reach_mm = step_mm * float(TAPS);
  vec2 texel = 1.0 / vec2(textureSize(u_entering, 0));
  float px_per_mm = u_pixels_per_mm_at_unit_depth / depth;
  vec3 sum = vec3(0.0), weight = vec3(0.0);
  for (int i = -TAPS; i <= TAPS; ++i) {
    vec2 uv = v_uv + u_direction * texel * (float(i) * step_mm * px_per_mm);
    float zi = texture(u_depth, uv).r;
    if (zi >= 1.0) continue;
    // Across a silhouette: the neighbour is more than the reach away in depth.
    if (abs(view_depth(zi) - depth) * u_mm_per_unit > reach_mm) continue;
    vec3 w = u_weights[abs(i)];
    sum += w * texture(u_entering, uv).rgb;
    weight += w;
  }
  vec3 blurred = sum / max(weight, vec3(1e-8));
  if (u_final == 1) blurred = blurred * texture(u_albedo, v_uv).rgb + texture(u_reflected, v_uv).rgb;
  o_color = vec4(blurred, 1.0);
}
