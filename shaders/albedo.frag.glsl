#version 450 core
// The albedo pass (paper §3.1, §4): the marble pattern at each visible pixel, from the object-
// space point and normal rebuilt from the G-buffer, stored as the diffuse colour. A screen
// pass, so every pixel is shaded once (see geometry.frag.glsl for why that matters), and it
// re-runs alone when only the pattern changes.
#include "gbuffer.glsl"
#include "marble_pattern.glsl"

in vec2 v_uv;
layout(location = 0) out vec4 o_albedo;
layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_normal;
uniform mat4 u_inv_model_view_proj;      // clip space -> the mesh's object space
uniform mat3 u_world_to_object_normal;   // transpose of the model matrix's 3x3

void main() {
  float z = texture(u_depth, v_uv).r;
  if (z >= 1.0) {
    o_albedo = vec4(0.0);
    return;
  }
  vec4 p = u_inv_model_view_proj * vec4(vec3(v_uv, z) * 2.0 - 1.0, 1.0);
  vec3 objectNormal = normalize(u_world_to_object_normal * decode_normal(texture(u_normal, v_uv).xy));
  o_albedo = vec4(marble_albedo(p.xyz / p.w, objectNormal), 1.0);
}
