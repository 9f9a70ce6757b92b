// The refined grid's texels to gather (bounce_refined_grid.glsl): appended by
// bounce_refine_mark.comp.glsl, read by the gather and the merge over the list, which BouncePass
// dispatches indirectly from `groups` (one workgroup per BOUNCE_REFINE_GROUP entries), so their
// cost follows the number of texels refined rather than the grid's size. BouncePass resets the
// header to {0, 1, 1, 0} before the mark.
layout(std430, binding = BUFFER_BOUNCE_REFINE_LIST) buffer BounceRefineList {
  uint groups[3];  // glDispatchComputeIndirect's arguments
  uint count;
  uint texels[];   // the refined grid's texel, x | y << 16
};

ivec2 bounce_refine_texel(uint k) { return ivec2(texels[k] & 0xFFFFu, texels[k] >> 16); }
