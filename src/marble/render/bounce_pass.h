#pragma once
// The bounce pass (`marble` only): the one diffuse bounce (shaders/bounce.glsl) gathered from the
// reflective shadow map at a quarter of the lighting pass's resolution each way (a sixteenth of its
// texels; an eighth of the frame's each way at the blur's default half), into an RGBA16F texture
// the lighting pass upsamples (shaders/bounce_upsample.glsl). Gathered at every lighting texel it
// was ~26 ms of the dragon's 800² lighting pass on llvmpipe; here ~2 (docs/performance.md, "The
// bounce gathered coarsely"); at half the lighting's resolution each way the light frames stayed
// at 1.4x. A second draw gathers the further bounces from the first, in screen space, on the same
// grid (shaders/bounce_further.frag.glsl), into a second RGBA16F texture. It reads no material
// parameter: the emitters' albedo is applied by the lighting pass.
#include "marble/gl/program.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

struct BounceInputs {
  GLuint normal, depth, bouncePosition, bounceNormal;  // the G-buffer's; the reflective shadow map
};

class BouncePass {
public:
  explicit BouncePass(const ShaderLibrary& shaders);
  // Full-resolution pixels per texel of the lighting pass (the blur's scale, 1 or 2); this pass
  // has bounceScale() of them.
  void resize(int width, int height, int lightingScale);
  void run(const BounceInputs& in, const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
           float lightTexelWorld, const ScreenRect& rect);
  GLuint bounceTexture() const { return bounce_.id(); }
  // The further bounces, gathered in screen space from the first (bounce_further.frag.glsl).
  GLuint furtherTexture() const { return further_.id(); }
  int scale() const { return scale_; }  // full-resolution pixels per texel
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 16; }  // two RGBA16F
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_, furtherProgram_;
  gl::VertexArray emptyVao_;
  gl::Texture bounce_, further_;
  gl::Framebuffer fbo_, furtherFbo_;
  int width_ = 0, height_ = 0, scale_ = 0;
  PassTimer timer_;
};

// Full-resolution pixels per texel of the bounce pass, given the lighting pass's.
constexpr int bounceScale(int lightingScale) { return 4 * lightingScale; }

}  // namespace marble
