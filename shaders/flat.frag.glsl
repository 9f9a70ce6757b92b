#version 450 core
// The floor of a frame's cost (issue 8): the mesh once, flat-shaded by facet normal.
in vec3 v_world_pos;
uniform vec3 u_light_pos;
uniform vec3 u_color;
out vec4 o_color;
void main() {
  vec3 n = normalize(cross(dFdx(v_world_pos), dFdy(v_world_pos)));
  float lambert = abs(dot(n, normalize(u_light_pos - v_world_pos)));
  o_color = vec4(u_color * (0.15 + 0.85 * lambert), 1.0);
}
