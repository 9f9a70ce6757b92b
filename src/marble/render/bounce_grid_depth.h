#pragma once
// The depth buffer of one of the bounce pass's grids (shaders/bounce_grid_depth.frag.glsl), so
// that the grid's full-screen draws shade only the texels whose pixel is stone
// (gl::setSurfaceOnlyScreenPassState), as the lighting pass and the blur do with BlurDepthPass's:
// llvmpipe skips a 4x4 block of fragments that all fail the depth test, which no branch in a
// shader does (docs/performance.md, "Twenty-first session: the bounce's draws skip the
// background"). Not BlurDepthPass's buffer at a coarser scale: that one takes the first stone
// pixel of a texel's block, the bounce's draws read pixel t * scale alone, and a texel tested
// on another pixel than the one its draw reads would change the picture. Where the test skips a
// texel its draw would have written the background's alpha -1, which the colour's clear already
// holds: the draws' outputs are bit-identical with and without the test.
#include "marble/gl/handles.h"
#include "marble/gl/program.h"
#include "marble/render/screen_rect.h"

namespace marble {

class BounceGridDepth {
public:
  // A buffer of width x height texels (at least the grid's: a larger one keeps the far plane
  // beyond the grid, so that it does not shrink a larger colour attachment's drawable area).
  void resize(int width, int height);
  // Fills the grid's gridWidth x gridHeight texels inside `cells` (the grid's texels, the draws'
  // scissor) from the G-buffer's depth bound at UNIT_LIGHTING_DEPTH; the rest holds the far plane.
  // `program`: shaders/bounce_grid_depth.frag.glsl. Leaves the depth test on (GL_ALWAYS).
  void fill(const gl::Program& program, GLuint emptyVao, int scale, int gridWidth, int gridHeight,
            const ScreenRect& cells) const;
  // Attaches it to `fbo` as its depth buffer, for gl::setSurfaceOnlyScreenPassState.
  void attachTo(GLuint fbo) const { gl::attachSurfaceDepth(fbo, depth_.id()); }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 4; }

private:
  gl::Texture depth_;
  gl::Framebuffer fbo_;  // the depth alone, for fill()
  int width_ = 0, height_ = 0;
};

}  // namespace marble
