#pragma once
// The albedo pass: the marble pattern evaluated once per visible pixel from the G-buffer's
// depth and normal (shaders/albedo.frag.glsl), into an RGBA8 texture -- the G-buffer's
// diffuse colour. Runs after the geometry pass, or alone when only the pattern changed.
// Programs are specialized per noise basis and mapping (gl/program_variants.h).
#include "marble/gl/program_variants.h"
#include "marble/render/pass_timer.h"
#include "marble/render/screen_rect.h"
#include "marble/render/view_setup.h"
#include "marble/scene/material.h"

namespace marble {

// The pattern's program variant (PAT_BASIS, PAT_MAPPING, and PAT_TURBULENCE_GRID when the
// turbulence is read from its baked grid) and its key (0..11), for every pass that evaluates
// the pattern. `turbulenceGrid`: the grid's texture (render/turbulence_texture.h), 0 for none.
std::vector<std::string> patternDefines(const Material& m, GLuint turbulenceGrid);
uint32_t patternVariantKey(const Material& m, GLuint turbulenceGrid);
// The uniforms of shaders/pattern_at_pixel.glsl (the view), and the grid bound to its unit; the
// material's (marble_pattern.glsl) come from uploadMaterialUniforms (material_uniforms.h).
void setPatternUniforms(const gl::Program& program, const glm::mat4& model, const CameraMatrices& camera,
                        GLuint turbulenceGrid);

class AlbedoPass {
public:
  explicit AlbedoPass(const ShaderLibrary& shaders);
  // `depthTexture`: the G-buffer's, of the same size (its depth test limits the pass to the surface).
  void resize(int width, int height, GLuint depthTexture);
  // Draws the surface inside `rect` (the mesh's screen rectangle); the rest is cleared to zero.
  void run(GLuint depthTexture, GLuint normalTexture, const glm::mat4& model, const CameraMatrices& camera,
           const Material& material, GLuint turbulenceGrid, const ScreenRect& rect);
  GLuint albedoTexture() const { return albedo_.id(); }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 4; }
  PassTimer& timer() { return timer_; }
  // Compiles the programs of every basis and mapping now (after a shader reload).
  void compileAll();

private:
  gl::ProgramVariants programs_;
  gl::VertexArray emptyVao_;
  gl::Texture albedo_;
  gl::Framebuffer fbo_;
  int width_ = 0, height_ = 0;
  PassTimer timer_;
};

}  // namespace marble
