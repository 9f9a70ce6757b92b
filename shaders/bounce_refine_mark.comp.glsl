#version 450 core
// The bounce pass's refinement, step one (`marble` only): which texels of the refined grid
// (bounce_refined_grid.glsl; half the coarse grid's scale) to gather the first bounce at. A texel
// is refined where the coarse first bounce cannot be trusted there: where the bilateral upsample's
// weights (bounce_bilateral.glsl) of the coarse samples around its pixel sum to less than
// BOUNCE_REFINE_BELOW, i.e. where they do not continue its surface (creases' folds, silhouettes,
// thin parts). Measured against Cycles over the ten reference scenes (docs/quality.md, "Seventeenth
// session: the first bounce refined by a list"): mean SSIM 0.8858 without the refinement, 0.8895 /
// 0.8902 / 0.8905 refining below 0.35 / 0.4 / 0.5; 0.4 is kept for the dragon's camera frame's cost
// (docs/performance.md: the gather over the list is most of it, and follows the texels refined).
// One invocation per coarse texel (i, j): it tests the three refined texels 2(i, j) + (1, 0),
// (0, 1), (1, 1) (texel 2(i, j) is the coarse sample itself, weight 1), reading the four coarse
// samples' surfaces once for all three, appends the ones that fail to the list
// (bounce_refine_list.glsl) and writes texel 2(i, j)'s flag.
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "gbuffer.glsl"
#include "deferred_common.glsl"

layout(local_size_x = BOUNCE_MARK_GROUP, local_size_y = BOUNCE_MARK_GROUP) in;
layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
#include "bounce_bilateral.glsl"
#include "bounce_refined_grid.glsl"
#include "bounce_refine_list.glsl"

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;  // the coarse first bounce (a < 0: none)
layout(binding = IMAGE_BOUNCE_REFINED, rgba16f) uniform writeonly image2D u_refined;
uniform ivec2 u_cell_origin;  // the first coarse texel of the object's rectangle (the dispatch covers the rest)

const float BOUNCE_REFINE_BELOW = 0.4;

void main() {
  ivec2 cell = u_cell_origin + ivec2(gl_GlobalInvocationID.xy);
  BounceGrid coarse = bounce_coarse_grid(), fine = bounce_refined_grid();
  if (any(greaterThan(cell, coarse.last))) return;
  vec2 fullSize = vec2(textureSize(u_depth, 0));
  ivec2 size = textureSize(u_depth, 0);
  // The three texels' depths first: most cells of the rectangle around the object see no surface.
  float depth[3];
  bool anySurface = false;
  for (int o = 1; o < 4; ++o) {
    ivec2 fi = 2 * cell + ivec2(o & 1, o >> 1), px = fi * fine.scale;
    bool inside = all(lessThanEqual(fi, fine.last)) && all(lessThan(px, size));
    depth[o - 1] = inside ? nearest_texel(u_depth, px).r : 1.0;  // GL_NEAREST (nearest_texel.glsl, by bounce_bilateral.glsl)
    anySurface = anySurface || depth[o - 1] < 1.0;
  }
  if (!anySurface) return;
  // The four coarse samples around, k = x + 2y, clamped to the grid as the upsample clamps them.
  bool present[4];
  vec3 Ps[4], Ns[4];
  ivec2 ps[4];
  for (int k = 0; k < 4; ++k) {
    ivec2 ic = min(cell + ivec2(k & 1, k >> 1), coarse.last);
    present[k] = nearest_texel(u_bounce, ic).a >= 0.0;
    ps[k] = ic * coarse.scale;
    Ps[k] = bounce_point(ps[k], fullSize);
    Ns[k] = bounce_normal(ps[k]);
  }
  bool anyRefined = false;
  for (int o = 1; o < 4; ++o) {
    if (depth[o - 1] >= 1.0) continue;  // the background, or outside the frame: nothing to gather
    ivec2 off = ivec2(o & 1, o >> 1);
    ivec2 fi = 2 * cell + off;
    ivec2 px = fi * fine.scale;
    vec3 P = surface_point((vec2(px) + 0.5) / fullSize, depth[o - 1]);
    vec3 N = bounce_normal(px);
    float reach = bounce_reach(P, N, px, fullSize);
    // Bilinear weights at the texel's pixel: halfway along the offset's axes, 0 across the others.
    vec2 f = 0.5 * vec2(off);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
      ivec2 c = ivec2(k & 1, k >> 1);
      float wb = (c.x == 1 ? f.x : 1.0 - f.x) * (c.y == 1 ? f.y : 1.0 - f.y);
      if (present[k] && wb > 0.0) weight += wb * bounce_match_point(P, N, reach, px, ps[k], Ps[k], Ns[k]);
    }
    if (weight < BOUNCE_REFINE_BELOW) {
      uint k = atomicAdd(count, 1u);
      texels[k] = uint(fi.x) | (uint(fi.y) << 16);
      atomicMax(groups[0], k / uint(BOUNCE_REFINE_GROUP) + 1u);
      anyRefined = true;
    }
  }
  // The flag (bounce_refined_grid.glsl); BouncePass cleared the rest to -1.
  if (anyRefined) imageStore(u_refined, fine.origin + 2 * cell, vec4(0.0));
}
