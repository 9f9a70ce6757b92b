// Which full-resolution pixel a texel of the subsurface blur's resolution stands for (scale 2
// by default, 1 at full resolution): pixel h * scale, its first, when that is stone; otherwise
// the first of its other scale x scale pixels that is (in row order), so that a texel is stone
// when any of its pixels is. Lighting (lighting.frag.glsl) and the blur's depth buffer
// (blur_depth.frag.glsl) take the same pixel. With pixel h * scale alone, the half-resolution
// silhouette crossed the full-resolution one, jumping by a texel from column to column; the
// blur's renormalization jumped with it and left a step of about 0.002 a few pixels inside the
// sphere's back-lit rim (tests/transmission_seams_gl_test.cpp; docs/quality.md "Tenth session:
// the rims kept, the half-resolution silhouette"). Now the blur's silhouette lies on or outside
// the full-resolution one. Of the alternatives measured there, the pixel nearest the camera left
// the step at 1.13x the test's threshold and the farthest took the far side of the torus across
// its occlusion edges; this one changes no texel that was already stone.
// The depth is read through its sampler (GL_NEAREST: nearest_texel.glsl).
#include "nearest_texel.glsl"

// pixel_depth: that pixel's depth as read here (what nearest_texel(depth, pixel).r gives), so that
// the callers do not read it again (one read per texel fewer: docs/performance.md, "Twenty-seventh
// session: ... s27-cost").
ivec2 blur_texel_pixel(sampler2D depth, ivec2 h, int scale, out float pixel_depth) {
  ivec2 last = textureSize(depth, 0) - 1;
  ivec2 first = min(h * scale, last);
  pixel_depth = nearest_texel(depth, first).r;
  if (pixel_depth < 1.0) return first;  // 1: the cleared background
  for (int k = 1; k < scale * scale; ++k) {
    // k % scale, k / scale for the scales there are, 1 and 2 (subsurfaceScale), as a mask and a
    // shift: llvmpipe has no vector integer division and divided lane by lane (the blur depth pass
    // 6.88 -> 4.60 M instructions, the lighting pass 91.08 -> 90.48 M: docs/performance.md).
    ivec2 p = min(h * scale + ivec2(k & (scale - 1), k >> (scale >> 1)), last);
    float d = nearest_texel(depth, p).r;
    if (d < 1.0) { pixel_depth = d; return p; }
  }
  return first;
}
