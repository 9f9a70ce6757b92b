#pragma once
// A colour framebuffer of a fixed size for headless rendering (RGBA8 unless told), with
// read-back of the RGBA8 kind. Its texture is filtered GL_LINEAR and clamped, so a later pass
// can sample it (FXAA does).
#include <utility>
#include <vector>

#include "marble/core/image.h"
#include "marble/gl/handles.h"

namespace marble {

class OffscreenTarget {
public:
  OffscreenTarget(int width, int height, GLenum internalFormat = GL_RGBA8);
  GLuint fbo() const { return fbo_.id(); }
  GLuint texture() const { return color_.id(); }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 4; }
  int width() const { return width_; }
  int height() const { return height_; }
  ImageRGBA8 read() const;  // top row first; RGBA8 targets only
  // Attaches `texture` (of the same size) at `attachment` of the framebuffer, besides its own
  // colour at GL_COLOR_ATTACHMENT0: e.g. the G-buffer's depth (GL_DEPTH_ATTACHMENT), for a
  // pass limited to the surface (gl::setSurfaceOnlyScreenPassState). The texture is borrowed
  // (gl::Borrowed): attached on every call, never compared with what was attached before.
  void attach(GLenum attachment, GLuint texture);

private:
  int width_, height_;
  gl::Texture color_;
  gl::Framebuffer fbo_;
};

}  // namespace marble
