// The light of the surface a mirror ray meets on screen (self_reflection.glsl's hit), read from the
// subsurface-blurred entering light (post pass, marble_diffuse). That light is stored at half the
// pixels' resolution, and its texel nearest the hit need not lie on the hit's surface: at a depth
// edge -- a thin part in front of another, the back-lit teapot's handle arm (two blur texels wide at
// 800^2) before its body -- it is often the part beside it, at another depth and with other light.
// So where the nearest texel's view depth (the blurred texture's alpha, blur_texel.glsl) lies
// farther from the hit's than `same_surface` (scene units: upsample_blurred's tolerance, the blur's
// reach plus a few pixels' footprint), the 3 x 3 texels around it are read and the one nearest the
// hit's depth is taken: the light of the hit's own surface, the choice the depth-aware upsample
// makes for a pixel (Kopf et al. 2007's joint bilateral upsampling, its nearest-depth fallback).
// Within the tolerance the nearest texel, as before: on one surface nothing changes.
// Measured (docs/quality.md, "Twenty-seventh session: the mirror image's light read on the hit's own
// surface"): teapot-back's Cycles glossy indirect light, a one-pixel line along the handle arm's inner
// edge, was 0.3-0.5 of Cycles' in marble's self-reflection there; the ten reference scenes' mean SSIM
// +0.00015 (teapot-back +0.0013, no scene down more than 0.00004). The search reaches one texel: a
// hit's depth edge farther than that from its nearest texel is not met (the 3 x 3 holds the nearest
// and its eight neighbours; 2 x 2 would miss the far side of a texel-wide part).
// Needs nearest_texel.glsl.
#ifndef MIRROR_HIT_LIGHT_GLSL
#define MIRROR_HIT_LIGHT_GLSL
vec3 mirror_hit_light(sampler2D blurred, ivec2 nearest, float hit_depth, float same_surface) {
  ivec2 last = textureSize(blurred, 0) - 1;
  vec4 best = nearest_texel(blurred, nearest);
  float off = abs(best.a - hit_depth);
  // The search's length depends on the data, so that a SIMD block none of whose pixels needs it
  // (nearly all: one surface) leaves the loop at once; llvmpipe runs both sides of an `if` for
  // every block with one lane inside, and the nine reads cost the camera frame 16.7 M instructions
  // in that form (docs/performance.md, "Twenty-seventh session: the mirror hit's light").
  int reads = off > same_surface ? 9 : 0;
  for (int k = 0; k < reads; ++k) {
    vec4 c = nearest_texel(blurred, clamp(nearest + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), last));
    float o = abs(c.a - hit_depth);
    if (o < off) {
      off = o;
      best = c;
    }
  }
  return best.rgb;
}
#endif
