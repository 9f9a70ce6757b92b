#version 450 core
// Pass 2 (paper §3): the mesh seen from the camera into the G-buffer: the normal (and, by the
// depth test, the depth). Position is not stored: later passes reconstruct it from the depth
// buffer. The marble pattern is not evaluated here but by the albedo pass, once per visible
// pixel: llvmpipe shades a whole 4x4 block for every small triangle it touches, so the
// dragon's 100,000 triangles cost 1.8 million fragment invocations for 130,000 covered
// pixels (GPUs lose the same way, in 2x2 quads).
#include "gbuffer.glsl"

in vec3 v_world_normal;

layout(location = 0) out vec2 o_normal;

void main() {
  // Not normalized: the octahedral encoding divides by the L1 norm, whatever the length (a
  // normalize per fragment is 1.8 million on the dragon at 800x800).
  vec3 n = v_world_normal;
  // Meshes with inward or inconsistent winding: face the normal toward the viewer.
  if (!gl_FrontFacing) n = -n;
  o_normal = encode_normal(n);
}
