#version 450 core
// The light's entry and exit layers (LightDepthPass's third draw, at a quarter of the light map's
// size): per texel, the distance from the light to the nearest surface (x: where the light's ray
// enters the first part it meets; of either facing, as the light's distance map, so that a
// grazing or wrongly wound triangle in front is never skipped; dragon-back's and buddha-back's
// SSIM the same to the digit as with the nearest surface facing the light) and to the nearest facing away (y: where it
// leaves that part). A point on the ray between the two lies in the stone, one beyond the exit in the
// air behind the first part, which one depth layer cannot tell from stone (docs/quality.md,
// "Nineteenth session"). Read by the hidden mirror image (hidden_mirror.glsl): the exit faces
// are, for a light behind the object, the glowing sides of its parts that face the camera, which
// a mirror ray meets behind the part in front of them. Both in one texture, so that each step of
// its march reads one texel. Drawn with both faces, no depth test and MIN blending
// (LightDepthPass), so each channel keeps its nearest.
// Facing is the triangle's own, its outside the interpolated normal's (session 20's layers,
// commit 435f961/c781c4b): the interpolated normal alone turns away from the light over the last
// triangles before the light's silhouette, which then counted as exits right behind their own
// entry. A mesh wound inward (the teapot of the reference scenes: its normals, computed from the
// winding, point in) is turned by its signed volume's sign (GpuMesh::woundInward); without it its
// exits lay before its entries and no stone was found anywhere. A mesh wound both ways is not.
in vec3 v_world_pos;
in vec3 v_world_normal;
#include "light_geometry.glsl"
uniform float u_none;           // "no such surface" (the clear value)
uniform float u_outward;        // -1 where the mesh is wound inward (its normals point in), else 1
layout(location = 0) out vec2 o_entry_exit;

void main() {
  vec3 toLight = light_vector(v_world_pos);
  float d = light_distance_of(v_world_pos);
  // The triangle's own normal (its plane's derivatives), turned to the outside the interpolated
  // normal points to.
  vec3 ng = cross(dFdx(v_world_pos), dFdy(v_world_pos));
  bool facing = u_outward * dot(ng, v_world_normal) * dot(ng, toLight) >= 0.0;
  o_entry_exit = vec2(d, facing ? u_none : d);
}
