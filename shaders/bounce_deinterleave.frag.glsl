#version 450 core
// The bounce pass's first draw's second step (`marble` only; BouncePass::gatherBounces): the first
// bounce's interleaved pattern evened out over its 2 x 2 blocks before anything reads it. The
// gather (bounce_gather.frag.glsl) turns the pattern by another quarter of its angular step in
// each texel of a 2 x 2 block, but the upsample
// (bounce_upsample.glsl) is bilinear, so near a texel's own pixel that texel's one turn dominates
// and a texel-sized mottle of the turns' luck remains (a thin emitter hit by one turn and missed
// by the next). Here each texel takes the mean of its 3 x 3 neighbours, weighted by a tent
// (1 2 1) x (1 2 1) and by how well each neighbour's surface continues its own (the upsample's
// match, bounce_bilateral.glsl): the tent gives each of the four turns the same weight (the texel's
// own 4, its two horizontal neighbours 2 + 2, the two vertical ones 2 + 2, the four corners
// 1 x 4), so on a smooth surface every texel sees the four turns evenly. This is interleaved
// sampling's discontinuity buffer (Keller & Heidrich 2001; Segovia et al. 2006, "Non-interleaved
// deferred shading of interleaved sample patterns") with the upsample's surface match as its
// geometry test. The merge reads the evened values (until session 25 the screen-space further
// bounces, bounce_further.frag.glsl, did too).
// Measured against Cycles (docs/quality.md, "Twenty-first session: the interleaved pattern evened
// out"): mean SSIM 0.9210 -> 0.9231 over the ten scenes, none lower; dragon-side +0.0068 and
// buddha-side +0.0047 over the pattern's four turns. The tent in the merge alone (the further
// bounces reading the raw grid) 0.9225; a cross (the diagonal turn left out) and the aligned 2 x 2
// block (a block's texels one value) lower; 5 x 5 (1 4 6 4 1)^2 0.9235 at three times the reads
// (+7.2 M instructions); as two separable draws, less (5 taps) or costlier (3 taps). Cost: +3.4 M
// instructions of the dragon's 800² camera and light frames (docs/performance.md).
// Error: on a curved surface the tent also blurs the bounce over +-1 texel (+-8 pixels at 800²):
// the bounce is smooth over tens of pixels (bounce_gather.frag.glsl), and the match keeps it from
// crossing folds and silhouettes; the refined grid's texels (bounce_refine_gather.comp.glsl) keep
// their own turns.
// (Sessions 21-24 the same draw also evened out the screen-space further bounces' grid; since
// session 25 the further bounces come from the world-space radiosity, further_radiosity.h.)
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "gbuffer.glsl"
#include "deferred_common.glsl"

layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
#include "bounce_bilateral.glsl"

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;  // the gather's (a < 0: the background)
uniform int u_scale;  // full-resolution pixels per texel of the gather's grid and this one
layout(location = 0) out vec4 o_bounce;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 own = nearest_texel(u_bounce, t);  // GL_NEAREST, t inside the grid (nearest_texel.glsl)
  if (own.a < 0.0) {
    o_bounce = own;  // the background stays the background
    return;
  }
  ivec2 px = t * u_scale;
  vec2 fullSize = vec2(textureSize(u_depth, 0));
  vec3 P = surface_point((vec2(px) + 0.5) / fullSize, nearest_texel(u_depth, px).r);  // px inside the frame (own.a >= 0)
  vec3 N = decode_normal(nearest_texel(u_normal, px).xy);
  float reach = bounce_reach(P, N, px, fullSize);
  ivec2 last = textureSize(u_bounce, 0) - 1;
  vec4 sum = 4.0 * own;
  float weight = 4.0;
  for (int k = 0; k < 9; ++k) {
    if (k == 4) continue;  // the texel itself, above
    ivec2 o = ivec2(k % 3, k / 3) - 1;
    ivec2 n = t + o;
    if (any(lessThan(n, ivec2(0))) || any(greaterThan(n, last))) continue;
    vec4 b = nearest_texel(u_bounce, n);  // GL_NEAREST (nearest_texel.glsl, by bounce_bilateral.glsl)
    if (b.a < 0.0) continue;  // the background (also every texel whose pixel lies outside the frame)
    float w = float((2 - abs(o.x)) * (2 - abs(o.y))) * bounce_match(P, N, reach, px, n * u_scale, fullSize);
    sum += w * b;
    weight += w;
  }
  o_bounce = sum / weight;
}
