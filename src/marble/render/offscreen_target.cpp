#include "marble/render/offscreen_target.h"

namespace marble {

OffscreenTarget::OffscreenTarget(int width, int height, GLenum internalFormat)
    : width_(width), height_(height), color_(gl::makeTexture2D(internalFormat, width, height, GL_LINEAR)),
      fbo_(gl::Framebuffer::create()) {
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
}

void OffscreenTarget::attach(GLenum attachment, GLuint texture) {
  glNamedFramebufferTexture(fbo_.id(), attachment, texture, 0);
}

ImageRGBA8 OffscreenTarget::read() const {
  ImageRGBA8 img{width_, height_, std::vector<uint8_t>(static_cast<size_t>(width_) * height_ * 4)};
  glNamedFramebufferReadBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  flipRows(img);
  return img;
}

}  // namespace marble
