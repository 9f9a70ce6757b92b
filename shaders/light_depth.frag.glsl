#version 450 core
// Pass 1 (paper §3, GPU Gems 1 ch. 16.3): the mesh seen from the light. We store the
// world-space distance from the light to the first surface it hits, so the lighting pass
// gets thickness in scene units rather than in non-linear depth-buffer values.
in vec3 v_world_pos;
uniform vec3 u_light_pos;       // point light: its position
uniform vec3 u_light_dir;       // directional light: unit vector the light travels along
uniform int u_light_directional;
layout(location = 0) out float o_distance;

void main() {
  o_distance = u_light_directional == 1 ? dot(v_world_pos, u_light_dir) : distance(v_world_pos, u_light_pos);
}
