#pragma once
// Screen-space subsurface scattering for the `marble` mode: two separable passes over the
// light that entered the stone (shaders/subsurface_blur.frag.glsl), at half resolution, on the
// surface inside the mesh's screen rectangle; alpha is the view depth. The post pass upsamples it (depth-aware),
// multiplies by the albedo and adds the reflected light.
#include "marble/gl/program_variants.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"
#include "marble/render/subsurface_profile.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

struct SubsurfaceBlurInputs {
  GLuint entering;  // at the blur's resolution; alpha: view depth (0 off the stone)
};

class SubsurfaceBlurPass {
public:
  explicit SubsurfaceBlurPass(const ShaderLibrary& shaders);
  // The frame's size; the pass's targets are 1/scale of it (subsurfaceScale). `depthTexture`:
  // of that size (BlurDepthPass): its depth test limits the blur to the surface.
  void resize(int width, int height, int scale, GLuint depthTexture);
  // `height`: the frame's (full-resolution) height; `rect`: the mesh's full-resolution rectangle.
  void run(const SubsurfaceBlurInputs& in, const CameraMatrices& camera, const Scene& scene, int height,
           const ScreenRect& rect);
  GLuint resultTexture() const { return result_.id(); }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 16; }
  PassTimer& timer() { return timer_; }
  // Every tap count's program now (reloadShaders: an error must show while the old ones are in use).
  void compileAll();

private:
  // One program per tap count (1..MAX_TAPS), built at its first use.
  gl::ProgramVariants programs_;
  const gl::Program& program(int taps);
  gl::VertexArray emptyVao_;
  // GL_NEAREST over the blur's GL_LINEAR input, for the centre's whole-texel read
  // (subsurface_blur.frag.glsl): the sampler's nearest read costs fewer instructions than
  // texelFetch on llvmpipe (nearest_texel.glsl), the same bits.
  gl::Sampler nearestSampler_;
  gl::Texture horizontal_, result_;
  gl::Framebuffer horizontalFbo_, resultFbo_;
  int width_ = 0, height_ = 0;
  PassTimer timer_;
  // The taps last cut (subsurfaceKernel), and for which stone.
  SubsurfaceKernel kernel_;
  WalkShape kernelWalk_;
  float kernelReachMm_ = 0.0f;
  float kernelCoreHalfWidthMm_ = 0.0f;
  bool kernelValid_ = false;
};

// 2 when the blur runs at half resolution, 1 at full.
int subsurfaceScale(const RenderSettings& settings);

// Taps per side (1..9): 1 x the square root of the reach in blur texels where the profile is
// widest on screen (quadratically spaced taps, subsurface_profile.h; `height`: the
// full-resolution frame's).
int subsurfaceTaps(const CameraMatrices& camera, const Scene& scene, int height);

// The uniforms of shaders/subsurface_common.glsl: depth range, millimetre scale on screen
// (`height`: the full-resolution frame's) and the blur's reach.
void setSubsurfaceUniforms(const gl::Program& program, const CameraMatrices& camera, const Scene& scene, int height);

}  // namespace marble
