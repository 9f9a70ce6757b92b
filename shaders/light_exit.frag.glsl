#version 450 core
// The light's exit layer (LightDepthPass's third draw, at the reflective shadow map's size): per
// texel, the distance from the light to the nearest surface facing away from it -- where the
// light's ray leaves the first part it meets. The light's distance map (light_depth.frag.glsl)
// holds where it entered that part, so a point on the ray between the two lies in the stone, one
// beyond the exit in the air behind the first part (docs/quality.md, "Nineteenth session"). Read
// by the hidden mirror image (hidden_mirror.glsl): the exit faces are, for a light behind the
// object, the glowing sides of its parts that face the camera, which a mirror ray meets behind
// the part in front of them. Drawn with both faces, no depth test and MIN blending
// (LightDepthPass), so the nearest exit stays; faces toward the light write "none".
// Facing is the triangle's own, its outside the interpolated normal's (session 20's layers,
// commit 435f961/c781c4b): the interpolated normal alone turns away from the light over the last
// triangles before the light's silhouette, which then counted as exits right behind their own
// entry. A file wound inward has its exit nearer than its entry: then no stone is found anywhere.
in vec3 v_world_pos;
in vec3 v_world_normal;
uniform vec3 u_light_pos;       // point light: its position
uniform vec3 u_light_dir;       // directional light: unit vector the light travels along
uniform int u_light_directional;
uniform float u_none;           // "no such surface" (the clear value)
layout(location = 0) out float o_exit;

void main() {
  vec3 toLight = u_light_directional == 1 ? -u_light_dir : normalize(u_light_pos - v_world_pos);
  float d = u_light_directional == 1 ? dot(v_world_pos, u_light_dir) : distance(v_world_pos, u_light_pos);
  // The triangle's own normal (its plane's derivatives), turned to the outside the interpolated
  // normal points to.
  vec3 ng = cross(dFdx(v_world_pos), dFdy(v_world_pos));
  bool facing = dot(ng, v_world_normal) * dot(ng, toLight) >= 0.0;
  o_exit = facing ? u_none : d;
}
