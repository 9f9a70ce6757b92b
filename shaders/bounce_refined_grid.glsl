// The bounce pass's output texture (BouncePass: the lighting pass reads it, bounce_upsample.glsl)
// holds two grids side by side: at the origin the coarse grid (texel i: full-resolution pixel
// i * scale; bounce_merge.frag.glsl), and right of it the refined grid at half its scale, whose
// texels with both indices even are the coarse grid's own (BounceGrid.evenFromCoarse) and whose
// others are gathered only where the coarse grid cannot be trusted (bounce_refine_mark.comp.glsl),
// alpha -1 elsewhere. The refined grid's texel 2i (even both ways) holds no bounce of its own; its
// alpha says whether any of its three odd neighbours i..i+1 was refined (>= 0) or none (-1), so that
// one read tells the upsample which grid a lighting texel takes.
// Needs from the includer: bounce_bilateral.glsl.

// The layout, from BouncePass (setBounceGridUniforms): the coarse grid's scale and both grids' sizes.
uniform int u_bounce_scale;          // full-resolution pixels per texel of the coarse grid
uniform ivec2 u_bounce_coarse_size;  // its texels
uniform ivec2 u_bounce_fine_size;    // the refined grid's texels (at half the scale)

BounceGrid bounce_coarse_grid() { return BounceGrid(u_bounce_scale, u_bounce_coarse_size - 1, ivec2(0), false); }

BounceGrid bounce_refined_grid() {
  return BounceGrid(u_bounce_scale / 2, u_bounce_fine_size - 1, ivec2(u_bounce_coarse_size.x, 0), true);
}
