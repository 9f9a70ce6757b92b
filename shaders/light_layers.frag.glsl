#version 450 core
// The light's entry and exit layers (LightDepthPass's third draw, at the reflective shadow map's
// size), for the bounce's test of whether light between two points would cross the stone
// (bounce.glsl, bounce_crosses_stone): per texel, the distance from the light to the nearest
// surface facing it (x: where the light's ray enters the first part it meets) and to the nearest
// facing away (y: where it leaves that part). Drawn with both faces, no depth test and MIN blending
// (LightDepthPass), so each channel keeps its nearest. A point on the ray between the two lies in
// the stone; one beyond the exit lies in the air behind the first part (between a coil and the body
// behind it), which one depth layer cannot tell from stone (docs/quality.md, "Nineteenth session").
// Facing is the triangle's own (since session 20; before, the interpolated normal's), its outside
// the interpolated normal's: a file wound inward has its exit nearer than its entry, and the test
// then finds no stone anywhere (the bounce as before).
in vec3 v_world_pos;
in vec3 v_world_normal;
uniform vec3 u_light_pos;       // point light: its position
uniform vec3 u_light_dir;       // directional light: unit vector the light travels along
uniform int u_light_directional;
uniform float u_none;           // "no such surface" (the clear value)
layout(location = 0) out vec2 o_entry_exit;

void main() {
  vec3 toLight = u_light_directional == 1 ? -u_light_dir : normalize(u_light_pos - v_world_pos);
  float d = u_light_directional == 1 ? dot(v_world_pos, u_light_dir) : distance(v_world_pos, u_light_pos);
  // The triangle's own normal (its plane's derivatives: one side of every triangle alike in the
  // light's view), turned to the outside the interpolated normal points to. The interpolated normal
  // alone turns away from the light across the last triangles before the light's silhouette, which
  // then counted as exits right behind their own entry: a chord of zero, through which the far
  // side's emitters (bounce_exits.frag.glsl) let all the light through.
  vec3 ng = cross(dFdx(v_world_pos), dFdy(v_world_pos));
  bool facing = dot(ng, v_world_normal) * dot(ng, toLight) >= 0.0;
  o_entry_exit = facing ? vec2(d, u_none) : vec2(u_none, d);
}
