#version 450 core
// The bounce pass's refinement, step three (`marble` only): each listed texel's first bounce
// (bounce_refine_gather.comp.glsl) merged with the further bounces at its point, as
// bounce_merge.frag.glsl merges the coarse grid's (bounce_merge.glsl), into the refined grid of the
// pass's output (bounce_refined_grid.glsl). Runs whenever the merge does (the material applied).
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "gbuffer.glsl"
#include "deferred_common.glsl"
#include "fresnel_f0.glsl"
#include "bounce_merge.glsl"

layout(local_size_x = BOUNCE_REFINE_GROUP) in;
layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
#include "bounce_bilateral.glsl"
#include "bounce_refined_grid.glsl"
#include "bounce_refine_list.glsl"

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_refined_first;    // the gather's
layout(binding = IMAGE_BOUNCE_REFINED, rgba16f) uniform writeonly image2D u_refined;

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= count) return;
  ivec2 t = bounce_refine_texel(k);
  BounceGrid fine = bounce_refined_grid();
  ivec2 px = t * fine.scale;
  vec2 fullSize = vec2(textureSize(u_depth, 0));
  vec3 P = surface_point((vec2(px) + 0.5) / fullSize, nearest_texel(u_depth, px).r);  // GL_NEAREST, px inside the frame (listed by the mark)
  imageStore(u_refined, fine.origin + t, bounce_merged(nearest_texel(u_refined_first, t), P));
}
