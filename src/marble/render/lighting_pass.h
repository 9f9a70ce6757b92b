#pragma once
// Pass 3: screen space. Reads the G-buffer and the light's distance map; writes the render
// mode's picture, linear and unclamped, into its own RGBA16F target (read by PostPass and by
// `--hdr`) -- or, for `marble`, the light entering the stone (read by the subsurface blur and
// the post pass, which adds the reflected light).
#include "marble/gl/program_variants.h"
#include "marble/render/environment_map.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

struct LightingInputs {
  GLuint albedo, normal, depth, lightDistance, lightDepth;
};

class LightingPass {
public:
  explicit LightingPass(const ShaderLibrary& shaders);
  void resize(int width, int height);
  // Draws inside `rect` only (everything else is cleared to zero), except the light-depth view.
  void run(const LightingInputs& in, const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
           const Material& material, const Scene& scene, float lightTexelWorld, const ScreenRect& rect,
           const EnvironmentMap* environment);  // used when the scene asks for a map; null: none loaded
  GLuint hdrTexture() const { return hdr_.id(); }  // every mode but `marble`: the picture
  GLuint enteringTexture() const { return entering_.id(); }  // `marble`: light entering the stone
  GLuint fbo() const { return fbo_.id(); }  // hdrTexture's
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 16; }
  PassTimer& timer() { return timer_; }
  // Compiles the program of every mode now (after a shader reload).
  void compileAll();

private:
  static std::vector<std::string> variantFor(RenderMode mode, const std::string& environment);
  gl::ProgramVariants programs_;
  gl::Texture hdr_, entering_;
  gl::Framebuffer fbo_, enteringFbo_;
  int width_ = 0, height_ = 0;
  gl::VertexArray emptyVao_;  // core profile needs a VAO bound even for attribute-less draws
  PassTimer timer_;
};

}  // namespace marble
