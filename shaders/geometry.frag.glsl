#version 450 core
// Pass 2 (paper §3): the mesh seen from the camera into the G-buffer: the normal (and, by the
// depth test, the depth). Position is not stored: later passes reconstruct it from the depth
// buffer. The marble pattern is not evaluated here but by the albedo pass, once per visible
// pixel: llvmpipe shades a whole 4x4 block for every small triangle it touches, so the
// dragon's 100,000 triangles cost 1.8 million fragment invocations for 130,000 covered
// pixels (GPUs lose the same way, in 2x2 quads).
#include "gbuffer.glsl"
#include "valid_reflection.glsl"

in vec3 v_world_pos;
in vec3 v_world_normal;

uniform vec3 u_camera_position;
// `marble` mode: also store the normal bent by Cycles' valid-reflection rule
// (valid_reflection.glsl), which needs the triangle's own normal: only this pass has it exactly.
uniform bool u_valid_reflection;

layout(location = 0) out vec2 o_normal;
// The normal the post pass's reflection terms read (the highlight, the mirrored light): bent by
// the rule in `marble` mode; not written in other modes (no draw buffer). The light's entry and
// the bounce read o_normal: bent, they darkened back-lit rims 3-4x below Cycles'
// (docs/quality.md, "Eighteenth session" and "Nineteenth session: ... valid-reflection").
// zw: the interpolated normal (o_normal's bits), so that the post pass tells a bent pixel
// (xy != zw) and takes a kept pixel's footprint steps from its neighbours' interpolated normals
// (post.frag.glsl, footprint_normal_steps) in the same texel read.
layout(location = 1) out vec4 o_specular_normal;

void main() {
  // Not normalized: the octahedral encoding divides by the L1 norm, whatever the length (a
  // normalize per fragment is 1.8 million on the dragon at 800x800).
  vec3 n = v_world_normal;
  // Meshes with inward or inconsistent winding: face the normal toward the viewer.
  if (!gl_FrontFacing) n = -n;
  vec2 kept = encode_normal(n);
  if (u_valid_reflection) {
    // The triangle's normal: the screen derivatives of the interpolated position lie in its
    // plane (exact for the primitive, helper lanes included). Faced toward the viewer, as
    // Cycles' Ng is. Where the rule keeps the normal, the interpolated one is stored unchanged
    // (the same bits as o_normal).
    vec3 g = cross(dFdx(v_world_pos), dFdy(v_world_pos));
    vec3 to_eye = u_camera_position - v_world_pos;
    if (dot(g, to_eye) < 0.0) g = -g;
    vec3 bent;
    o_specular_normal = vec4(valid_reflection_bend(g, to_eye, n, bent) ? encode_normal(bent) : kept, kept);
  }
  o_normal = kept;
}
