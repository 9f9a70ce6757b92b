#version 450 core
// Pass 2 (paper §3): the mesh seen from the camera into the G-buffer. The marble pattern is
// evaluated here and stored as the diffuse colour (paper §4). Position is not stored: the
// lighting pass reconstructs it from the depth buffer.
#include "gbuffer.glsl"
#include "marble_pattern.glsl"

in vec3 v_object_pos;
in vec3 v_object_normal;
in vec3 v_world_normal;

layout(location = 0) out vec4 o_albedo;
layout(location = 1) out vec2 o_normal;

void main() {
  vec3 n = normalize(v_world_normal);
  // Meshes with inward or inconsistent winding: face the normal toward the viewer.
  if (!gl_FrontFacing) n = -n;
  o_albedo = vec4(marble_albedo(v_object_pos, normalize(v_object_normal)), 1.0);
  o_normal = encode_normal(n);
}
