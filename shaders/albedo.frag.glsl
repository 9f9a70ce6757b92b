#version 450 core
// The albedo pass (paper §3.1, §4): the marble pattern at each visible pixel, from the object-
// space point and normal rebuilt from the G-buffer, stored as the diffuse colour. A screen
// pass, so every pixel is shaded once (see geometry.frag.glsl for why that matters), and it
// re-runs alone when only the pattern changes.
#include "gbuffer.glsl"
#include "marble_pattern.glsl"
#include "pattern_at_pixel.glsl"

in vec2 v_uv;
layout(location = 0) out vec4 o_albedo;
layout(binding = UNIT_ALBEDO_DEPTH) uniform sampler2D u_depth;
layout(binding = UNIT_ALBEDO_NORMAL) uniform sampler2D u_normal;

void main() {
  float z = texture(u_depth, v_uv).r;
  if (z >= 1.0) {
    o_albedo = vec4(0.0);
    return;
  }
  o_albedo = vec4(albedo_at_pixel(v_uv, z, decode_normal(texture(u_normal, v_uv).xy)), 1.0);
}
