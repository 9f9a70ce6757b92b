#pragma once
// Last pass: linear HDR light to the target framebuffer. For `marble` it also composes the
// frame (the subsurface-blurred light times the albedo, plus the reflected light: GGX and the
// environment), then exposes, tone maps (Khronos PBR Neutral) and sRGB-encodes it; the
// paper's modes and the buffer views pass through unchanged. It draws only the surface inside
// the mesh's screen rectangle (the target has the G-buffer's depth attached:
// gl::setSurfaceOnlyScreenPassState); the rest of the target is cleared to the background colour.
#include "marble/gl/program_variants.h"
#include "marble/render/environment_map.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

struct PostInputs {
  GLuint hdr = 0;    // every mode but `marble`: the lighting pass's picture
  GLuint depth = 0;  // the G-buffer's depth (where the background is)
  // `marble` only:
  GLuint blurred = 0, albedo = 0, normal = 0, lightShadow = 0;
  GLuint mirrorHit = 0;  // the lighting pass's mirror hits (self_reflection.glsl)
};

// The frame's camera and light (the `marble` composition needs them), and the model matrix
// (for the pattern, DiffuseSource::Pattern).
struct PostView {
  const CameraMatrices& camera;
  const LightMatrices& light;
  float lightTexelWorld;
  const EnvironmentMap* environment;  // the loaded map, or null
  const glm::mat4& model;
  // The baked turbulence (render/turbulence_texture.h), read by DiffuseSource::Pattern frames
  // (ignored by the others); 0: the pattern evaluated per pixel.
  GLuint turbulenceGrid = 0;
};

// Where a `marble` frame's diffuse part (blurred light x albedo) comes from: DIFFUSE_SOURCE in
// shaders/post.frag.glsl, which explains the choice. The renderer picks the cheapest one whose
// inputs are current.
enum class DiffuseSource {
  Pattern = 0,       // the albedo changed: evaluated here, and written to the albedo texture
  StoredAlbedo = 1,  // the light changed: the albedo texture's
  Stored = 2,        // neither: the diffuse texture written by an earlier frame
};

// What a DiffuseSource::Pattern frame keeps of, or takes from, the frame before it besides the
// albedo: SURFACE_REUSE in shaders/post.frag.glsl. In a frame that changed only the pattern
// (`--motion pattern`, the panel's pattern sliders) the upsampled blurred light and the reflected
// light are what the previous frame computed; the renderer stores them in the first such frame
// and reads them back in the next ones (Renderer::drawFrame says when they are current).
enum class SurfaceReuse {
  None = 0,   // computed, not stored (the camera's and the light's frames: nothing to reuse)
  Store = 1,  // computed and written to surfaceLightTexture() and surfaceReflectedTexture()
  Read = 2,   // read from them
};

// FXAA's luma of a display colour (fxaa_luma in post.frag.glsl).
float fxaaLuma(const glm::vec3& displayColor);

// `marble` mode: the attenuation per object unit with which the vein models are seen through the
// polish (diffusionAttenuationMm x mm_per_unit; 0 for the paper's model, a surface pattern).
float seenVeinAttenuation(const Scene& scene);

class PostPass {
public:
  explicit PostPass(const ShaderLibrary& shaders);
  // What the pass writes: the display picture (alpha 1), the display picture with its luma in
  // alpha (what FXAA reads), or the linear HDR picture with coverage in alpha -- what `--hdr`
  // saves, composed by the same code as what is shown.
  enum class Output { Display, DisplayWithLuma, Linear };
  // targetFbo: of the frame's size, with the G-buffer's depth attached (OffscreenTarget::attach)
  // and, for `marble` from DiffuseSource Pattern or StoredAlbedo, diffuseTexture() at
  // GL_COLOR_ATTACHMENT1 and (Pattern) the albedo texture at GL_COLOR_ATTACHMENT2, which the
  // pass writes too.
  // SurfaceReuse::Store: the two surface textures at GL_COLOR_ATTACHMENT3 and 4 of targetFbo too
  // (Read: not attached, they are sampled); only with DiffuseSource::Pattern.
  void run(const PostInputs& in, const Scene& scene, const PostView& view, GLuint targetFbo, int width, int height,
           const ScreenRect& rect, Output output, DiffuseSource source, SurfaceReuse reuse = SurfaceReuse::None);
  void resize(int width, int height);
  GLuint diffuseTexture() const { return diffuse_.id(); }  // `marble`: blurred light x albedo, RGBA16F
  // SurfaceReuse: the upsampled blurred light and the reflected light, RGBA32F (made on first use:
  // 32 bytes a pixel that only pattern-changing frames need).
  GLuint surfaceLightTexture();
  GLuint surfaceReflectedTexture();
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * (surfaceLight_ ? 40 : 8); }
  PassTimer& timer() { return timer_; }
  void compileAll();

private:
  // directional: the light's kind, a constant of the program (LIGHT_DIRECTIONAL, shaders/light_geometry.glsl).
  const gl::Program& program(bool marble, int envKind, DiffuseSource source, const Material& material,
                            GLuint turbulenceGrid, bool directional, SurfaceReuse reuse = SurfaceReuse::None);
  gl::ProgramVariants programs_;
  gl::VertexArray emptyVao_;
  gl::Texture diffuse_;
  gl::Texture surfaceLight_, surfaceReflected_;
  int width_ = 0, height_ = 0;
  PassTimer timer_;
};

}  // namespace marble
