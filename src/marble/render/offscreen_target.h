#pragma once
// An RGBA8 colour framebuffer of a fixed size for headless rendering, with read-back.
#include "marble/core/image.h"
#include "marble/gl/handles.h"

namespace marble {

class OffscreenTarget {
public:
  OffscreenTarget(int width, int height);
  GLuint fbo() const { return fbo_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  ImageRGBA8 read() const;  // top row first

private:
  int width_, height_;
  gl::Texture color_;
  gl::Framebuffer fbo_;
};

}  // namespace marble
