#pragma once
// Pass 3: screen space. Reads the G-buffer and the light's distance map; writes the render
// mode's picture, linear and unclamped, into its own RGBA16F target (read by PostPass and by
// `--hdr`) -- or, for `marble`, the light entering the stone (read by the subsurface blur and
// the post pass, which adds the reflected light), at the blur's resolution (half by default):
// the blur spreads it over millimetres, so a quarter of the pixels carry it.
#include <array>
#include <optional>
#include <utility>

#include "marble/gl/program_variants.h"
#include "marble/render/bounce_pass.h"
#include "marble/render/environment_map.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"
#include "marble/scene/slab_transport.h"

namespace marble {

struct LightingInputs {
  GLuint albedo, normal, depth, lightDistance, lightDepth;
  GLuint bounce;    // `marble`: the bounce pass's gather, all bounces (BouncePass)
  BounceGridLayout bounceGrid;  // and where it holds its grids
  GLuint bounceEntry;  // `marble`: the first bounce at the light's entries (BouncePass)
  GLuint lightLayers;  // `marble`: where the light enters and leaves the first part it meets (LightDepthPass)
};

class LightingPass {
public:
  explicit LightingPass(const ShaderLibrary& shaders);
  // `enteringScale`: full-resolution pixels per texel of the entering light (the blur's, 1 or 2);
  // `depthTexture`: the G-buffer's, `enteringDepth`: the one of the entering light's resolution
  // (BlurDepthPass): their depth test limits the pass to the surface.
  void resize(int width, int height, int enteringScale, GLuint depthTexture, GLuint enteringDepth);
  // Draws the surface inside `rect` only (everything else is cleared to zero), except the
  // light-depth view, which shows the light's map whole.
  void run(const LightingInputs& in, const CameraMatrices& camera, const LightMatrices& lightM, const Light& light,
           const Material& material, const Scene& scene, float lightTexelWorld, const ScreenRect& rect,
           const EnvironmentMap* environment);  // used when the scene asks for a map; null: none loaded
  GLuint hdrTexture() const { return hdr_.id(); }  // every mode but `marble`: the picture
  GLuint enteringTexture() const { return entering_.id(); }  // `marble`: light entering the stone
  // `marble`: per entering texel, the pixel its mirror ray meets (self_reflection.glsl), -1 none.
  GLuint mirrorHitTexture() const { return mirrorHit_.id(); }
  size_t bytes() const {
    return static_cast<size_t>(width_) * height_ * 8 + static_cast<size_t>(enteringWidth_) * enteringHeight_ * 16;
  }
  PassTimer& timer() { return timer_; }
  // Compiles the program of every mode now (after a shader reload).
  void compileAll();

private:
  // The light's kind a constant of the program (LIGHT_DIRECTIONAL, shaders/light_geometry.glsl).
  static std::vector<std::string> variantFor(RenderMode mode, const std::string& environment, bool directional);
  gl::ProgramVariants programs_;
  gl::Texture hdr_, entering_, mirrorHit_;
  gl::Framebuffer fbo_, enteringFbo_;
  int width_ = 0, height_ = 0, enteringWidth_ = 0, enteringHeight_ = 0, enteringScale_ = 0;
  gl::VertexArray emptyVao_;  // core profile needs a VAO bound even for attribute-less draws
  PassTimer timer_;
  SlabTransport slab_;  // the transmission's table for the scattering coefficients in slabFor_
  float chordDecayMm_ = 0.0f;  // transmission_chord.glsl's decay per mm, for the coefficients in slabFor_
  // slab_ per channel as segments (ln T at nodes k, k + 1), as lighting.frag.glsl's u_slab_segment_*:
  // the two floats' bits in one double (packFloatPair), not a value
  std::array<std::array<double, kSlabTransportNodes - 1>, 3> slabSegments_{};
  float litFaceRingMm_ = 0.0f;  // mirror_lit_face.glsl's ring (walkRingRadiusMm), for the coefficients in slabFor_
  std::optional<std::pair<glm::vec3, glm::vec3>> slabFor_;  // (sigma_a_mm, sigma_s_mm)
};

}  // namespace marble
