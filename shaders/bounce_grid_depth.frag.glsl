#version 450 core
// The depth buffer of one of the bounce pass's grids (BounceGridDepth): texel t holds the
// G-buffer's depth at full-resolution pixel t * u_scale, the one pixel the grid's draws read for
// it (bounce_gather.frag.glsl, bounce_deinterleave.frag.glsl, bounce_merge.frag.glsl), so that the depth test against the far-plane triangle passes exactly
// where they find depth < 1 and gather.
// The grids are rounded up, so t * u_scale lies inside the frame for every texel of them.
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;  // the G-buffer's (GL_NEAREST)
#include "nearest_texel.glsl"
uniform int u_scale;  // full-resolution pixels per texel of the grid
void main() {
  // Through the sampler: the same texel and bits as texelFetch, fewer instructions (nearest_texel.glsl).
  gl_FragDepth = nearest_texel(u_depth, ivec2(gl_FragCoord.xy) * u_scale).r;
}
