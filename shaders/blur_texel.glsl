// Which full-resolution pixel a texel of the subsurface blur's resolution stands for (scale 2
// by default, 1 at full resolution): of the scale x scale pixels it covers, the one nearest the
// camera, so that a texel is stone when any of its pixels is. Lighting (lighting.frag.glsl) and
// the blur's depth buffer (blur_depth.frag.glsl) take the same pixel. With the texel's corner
// pixel alone, the half-resolution silhouette crossed the full-resolution one, jumping by a texel
// from column to column; the blur's renormalization jumped with it and left a step of about
// 0.002 a few pixels inside the sphere's back-lit rim (tests/transmission_seams_gl_test.cpp,
// docs/quality.md "Tenth session: the rims kept, the half-resolution silhouette"). Taken so, the
// blur's silhouette lies on or outside the full-resolution one.
ivec2 blur_texel_pixel(sampler2D depth, ivec2 h, int scale) {
  ivec2 last = textureSize(depth, 0) - 1;
  ivec2 best = min(h * scale, last);
  float nearest = texelFetch(depth, best, 0).r;
  for (int y = 0; y < scale; ++y) {
    for (int x = 0; x < scale; ++x) {
      ivec2 p = min(h * scale + ivec2(x, y), last);
      float z = texelFetch(depth, p, 0).r;
      if (z < nearest) {
        nearest = z;
        best = p;
      }
    }
  }
  return best;
}
