#pragma once
// The depth buffer of the subsurface blur's resolution (shaders/blur_depth.frag.glsl), so
// that the `marble` lighting pass and the blur, which run at that resolution, shade only the
// surface (gl::setSurfaceOnlyScreenPassState): a quarter of a pixel pass's cost at half
// resolution. Made from the G-buffer's depth, once per view. At full resolution the G-buffer's
// depth serves as it is.
#include "marble/gl/borrowed.h"
#include "marble/gl/program.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"

namespace marble {

class BlurDepthPass {
public:
  explicit BlurDepthPass(const ShaderLibrary& shaders);
  // The frame's size and the blur's scale (subsurfaceScale); gBufferDepth: the G-buffer's.
  // Returns true when the buffer was made anew (its content is then to be filled by run()): on a
  // change of size or scale. The G-buffer's depth is borrowed (gl::Borrowed): it is taken anew
  // on every call, and a new G-buffer comes with a new frame size.
  bool resize(int width, int height, int scale, GLuint gBufferDepth);
  // Fills it inside `rect` (the mesh's full-resolution rectangle); the rest holds the far plane.
  // Does nothing at scale 1.
  void run(const ScreenRect& rect);
  // The depth texture at the blur's resolution (the G-buffer's own at scale 1).
  GLuint depthTexture() const { return scale_ == 1 ? gBufferDepth_.id() : depth_.id(); }
  size_t bytes() const { return scale_ == 1 ? 0 : static_cast<size_t>(width_) * height_ * 4; }
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_;
  gl::VertexArray emptyVao_;
  gl::Texture depth_;
  gl::Framebuffer fbo_;
  int width_ = 0, height_ = 0, scale_ = 0;
  gl::Borrowed gBufferDepth_;
  PassTimer timer_;
};

}  // namespace marble
