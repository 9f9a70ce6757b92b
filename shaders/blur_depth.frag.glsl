#version 450 core
// The depth buffer of the subsurface blur's resolution (half by default): texel h holds the
// depth of the full-resolution pixel it stands for (blur_texel.glsl). With it attached, the half-resolution lighting and blur passes test
// depth and shade the surface only (gl::setSurfaceOnlyScreenPassState), as the full-resolution
// passes do with the G-buffer's own depth.
layout(binding = UNIT_SCREEN_INPUT) uniform sampler2D u_depth;  // the G-buffer's
uniform int u_scale;
#include "blur_texel.glsl"
void main() {
  float depth;
  blur_texel_pixel(u_depth, ivec2(gl_FragCoord.xy), u_scale, depth);  // GL_NEAREST: nearest_texel.glsl
  gl_FragDepth = depth;
}
