#version 450 core
// Pass 1 (paper §3, GPU Gems 1 ch. 16.3): the mesh seen from the light. We store the
// world-space distance from the light to the first surface it hits, so the lighting pass
// gets thickness in scene units rather than in non-linear depth-buffer values. Beside it, the
// cosine between that surface's normal and the direction to the light: how much of the light
// enters the stone there (translucent shadow maps, Dachsbacher & Stamminger 2003, store the
// entering irradiance with the depth; the lighting pass applies the Fresnel factor and the light's
// falloff). |cos|: both faces are drawn, and files wound inward must still let light in.
in vec3 v_world_pos;
in vec3 v_world_normal;
uniform vec3 u_light_pos;       // point light: its position
uniform vec3 u_light_dir;       // directional light: unit vector the light travels along
uniform int u_light_directional;
layout(location = 0) out vec2 o_distance_cos;  // distance, entry cosine

void main() {
  vec3 toLight = u_light_directional == 1 ? -u_light_dir : normalize(u_light_pos - v_world_pos);
  float d = u_light_directional == 1 ? dot(v_world_pos, u_light_dir) : distance(v_world_pos, u_light_pos);
  o_distance_cos = vec2(d, abs(dot(normalize(v_world_normal), toLight)));
}
