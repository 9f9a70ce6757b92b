// The bounce pass's output texture (BouncePass: the lighting pass reads it, bounce_upsample.glsl)
// holds two grids side by side: at the origin the coarse grid (texel i: full-resolution pixel
// i * scale; bounce_merge.frag.glsl), and right of it the refined grid at half its scale, whose
// texels with both indices even are the coarse grid's own (BounceGrid.evenFromCoarse) and whose
// others are gathered only where the coarse grid cannot be trusted (bounce_refine_mark.comp.glsl),
// alpha -1 elsewhere. The refined grid's texel 2i (even both ways) holds no bounce of its own; its
// alpha says whether any of its three odd neighbours i..i+1 was refined (>= 0) or none (-1), so that
// one read tells the upsample which grid a lighting texel takes.
// Needs from the includer: bounce_bilateral.glsl.

BounceGrid bounce_coarse_grid(int scale) { return BounceGrid(scale, bounce_grid_size(scale) - 1, ivec2(0), false); }

BounceGrid bounce_refined_grid(int coarseScale) {
  int scale = coarseScale / 2;
  return BounceGrid(scale, bounce_grid_size(scale) - 1, ivec2(bounce_grid_size(coarseScale).x, 0), true);
}
