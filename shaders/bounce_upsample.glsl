// The lighting pass's bounce (`marble`): the bounce pass's coarse samples (the first bounce,
// bounce_gather.frag.glsl, and the further bounces added to it, bounce_merge.frag.glsl; one per
// 4 x 4 lighting texels; since session 17 also one per 2 x 2 where the coarse ones fail,
// bounce_refined_grid.glsl) brought to a lighting texel, weighted as a bilateral upsample
// (bounce_bilateral.glsl: bilinear in the coarse grid, times how well each sample's surface
// continues the texel's own, both read from the G-buffer). Where no coarse sample around lies on this surface (a part thinner than the coarse grid), a
// neighbour's is taken. Such a part, in front of another, takes a wrong bounce: the marble golden's
// knot (a 12-pixel tube at 160²) is darker by up to 123 levels in a few pixels along the edges
// where one tube crosses another (docs/quality.md). Gathering in place there instead
// (bounce_gather) cost the dragon's light frames ~8-10 ms on llvmpipe even where it ran for a few
// pixels (its shader evaluates a branch under a lane mask): not kept.
// Error (docs/quality.md, "One bounce gathered coarsely"): against the gather at every lighting
// texel, relative RMSE 0.05 and SSIM 0.98 on the dragon lit from the side at 800² (SSIM within
// 0.003 of it against Cycles in the ten reference scenes): the bounce's finest emitters (1/32 of
// the light map's width, ~15 pixels on an object filling 500) are a little finer than the coarse
// grid, so it comes out a little smoother.
// Needs from the includer: u_depth, u_normal (the G-buffer's), gbuffer.glsl, deferred_common.glsl,
// marble_shading.glsl (f0_from_ior).
#include "bounce_bilateral.glsl"
#include "bounce_refined_grid.glsl"

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;  // both grids (bounce_refined_grid.glsl)
uniform float u_ior;         // the emitters' Fresnel F0 (the mirrored part's Fresnel factor)

// Irradiance / PI that all bounces bring to the surface at full-resolution pixel px (point P,
// normal N), before P's own albedo and entry; with it, over P's albedo, the bounce's light that P's
// specular layer mirrors toward the camera (bounce.glsl, since session 10), times `mirrored`: 0
// where P's mirror ray meets a surface the camera sees, whose light the post pass mirrors instead
// (self_reflection.glsl), or an exit face hidden from it (hidden_mirror.glsl; the same light counted
// once), else 1.
vec3 marble_bounce(vec3 P, vec3 N, ivec2 px, float mirrored) {
  // rgb: the emitters' albedo and Fresnel factors already applied (bounce_merge.glsl). From the
  // refined grid where its texel at or just before px (the first of the four the upsample reads)
  // was refined or, for a coarse sample's own texel, has a refined neighbour; from the coarse grid
  // elsewhere, exactly as before the refinement. One upsample either way, its grid chosen per texel.
  BounceGrid fine = bounce_refined_grid();
  // px / fine.scale as a shift (the scale is 2 or 4, bounceScale / 2; px >= 0): llvmpipe divides
  // an ivec2 by a uniform lane by lane (-0.27 M instructions of the dragon's 800^2 camera frame).
  bool refined = nearest_texel(u_bounce, fine.origin + min(px >> findLSB(fine.scale), fine.last)).a >= 0.0;  // GL_NEAREST
  vec4 b = bounce_bilateral_in(u_bounce, refined ? fine : bounce_coarse_grid(), P, N, px);
  float F0 = f0_from_ior(u_ior).x;
  // The mirrored part: radiance emitters' albedo x b.a x F at the view's cosine. It is reflected
  // light, but returned with the light entering the stone, which the post pass multiplies by the
  // albedo at P, so divided by it: taken as the emitters' (the base colour), the two cancel. Exact
  // for a flat stone; on a veined one the mirror image is tinted by the vein under it (off by the
  // vein's contrast to the base colour), and it is spread by the subsurface blur's millimetres.
  float m = 1.0 - clamp(dot(N, normalize(u_camera_pos - P)), 0.0, 1.0), m2 = m * m;
  float Fv = F0 + (1.0 - F0) * m2 * m2 * m;
  return u_light_radiance * (b.rgb + mirrored * Fv * b.a);
}
