#version 450 core
// The bounce pass's refinement, step two (`marble` only): the first bounce (bounce.glsl) gathered
// at each listed texel of the refined grid (bounce_refine_mark.comp.glsl), as
// bounce_gather.frag.glsl gathers it at the coarse grid's texels, into the refined texels' image
// (their merge, bounce_refine_merge.comp.glsl, follows). Dispatched indirectly over the list: its
// cost follows the texels refined, where a draw over the fine grid under a mask costs nearly the
// whole grid on llvmpipe (docs/performance.md, "Sixteenth session: the first bounce refined").
#include "gbuffer.glsl"
#include "paper_shading.glsl"
#include "deferred_common.glsl"
#include "rotation.glsl"
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
// The bounce's occlusion near the receiver against this depth (camera-side gathers only).
#define BOUNCE_SCREEN_OCCLUSION
#include "bounce_screen_occlusion.glsl"
#include "bounce.glsl"
#include "bounce_radial_stratum.glsl"

layout(local_size_x = BOUNCE_REFINE_GROUP) in;
layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
#include "bounce_refine_list.glsl"
layout(binding = IMAGE_BOUNCE_REFINED_FIRST, rgba16f) uniform writeonly image2D u_refined_first;
uniform int u_scale;  // full-resolution pixels per texel of the refined grid

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= count) return;
  ivec2 t = bounce_refine_texel(k);
  ivec2 px = t * u_scale;
  vec2 size = vec2(textureSize(u_depth, 0));
  vec3 P = surface_point((vec2(px) + 0.5) / size, nearest_texel(u_depth, px).r);  // GL_NEAREST, px inside the frame (listed by the mark)
  vec3 N = decode_normal(nearest_texel(u_normal, px).xy);
  // The interleaved pattern's turn as the coarse grid's (bounce_gather.frag.glsl) by the texel's
  // place in its 2 x 2 block, and another eighth of a step: the refined texels' pattern lies between
  // the coarse ones' turns, so where an upsample mixes the two grids it mixes eight turns. Not
  // evened out over neighbours as the coarse grids are (bounce_deinterleave.frag.glsl): this offset's
  // luck moves the scenes by at most 0.001 of SSIM (docs/quality.md, "Twenty-first session: the
  // further bounces' pattern evened out").
  ivec2 q = t & 1;
  imageStore(u_refined_first, t, bounce_gather(P, N, normalize(u_camera_pos - P), 0.25 * float(q.x + 2 * q.y) + 0.125,
                                                     BOUNCE_RADIAL_MIDDLE));  // not evened out: bounce_radial_stratum.glsl
}
