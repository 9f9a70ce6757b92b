#pragma once
// Antialiasing after the post pass: FXAA (Lottes; shaders/fxaa.frag.glsl cites the algorithm)
// from the display image to the target framebuffer. Flat regions come out bit for bit as they
// went in; only pixels on a contrast edge are blended across it.
#include "marble/gl/program.h"
#include "marble/render/pass_timer.h"
#include <vector>

#include "marble/render/screen_rect.h"

namespace marble {

class FxaaPass {
public:
  explicit FxaaPass(const ShaderLibrary& shaders);
  // `displayImage`: the picture as displayed (RGBA8, sRGB-encoded, its luma in alpha), width x
  // height, filtered GL_LINEAR and clamped to its edge (the search reads between texels).
  // Only `spans` are filtered; outside them the image holds nothing but `background` (the post
  // pass's clear), which the target is cleared to (opaque: the luma in alpha stays behind).
  void run(GLuint displayImage, GLuint targetFbo, int width, int height, const std::vector<ScreenRect>& spans,
           const glm::vec3& background);
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_;
  gl::VertexArray emptyVao_;
  PassTimer timer_;
};

}  // namespace marble
