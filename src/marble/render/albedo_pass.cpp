#include "marble/render/albedo_pass.h"

#include "marble/gl/checked_calls.h"
#include "marble/noise/marble_pattern.h"
#include "marble/noise/turbulence_grid.h"
#include "marble/render/material_uniforms.h"
#include "marble/render/shader_constants.h"
#include "marble/render/turbulence_texture.h"

namespace marble {

AlbedoPass::AlbedoPass(const ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "albedo.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {
  programs_.get(patternDefines(Material{}, 0));  // the default material's, so a broken shader shows at once
}

std::vector<std::string> patternDefines(const Material& m, GLuint turbulenceGrid) {
  std::vector<std::string> d = {"PAT_BASIS " + std::to_string(static_cast<int>(m.basis)),
                                "PAT_MAPPING " + std::to_string(static_cast<int>(m.mapping)),
                                "PAT_VEIN_MODEL " + std::to_string(veinUniformValues(m).model)};
  if (turbulenceGrid != 0) d.push_back("PAT_TURBULENCE_GRID " + std::to_string(turbulenceGridDimensions(m)));
  return d;
}

uint32_t patternVariantKey(const Material& m, GLuint turbulenceGrid) {
  // The grid's dimensions follow from the mapping: one bit says whether it is read.
  return static_cast<uint32_t>(m.basis) * 3u + static_cast<uint32_t>(m.mapping) + (turbulenceGrid != 0 ? 6u : 0u) +
         12u * static_cast<uint32_t>(veinUniformValues(m).model);
}

void setPatternUniforms(const gl::Program& p, const glm::mat4& model, const CameraMatrices& camera,
                        GLuint turbulenceGrid) {
  p.set("u_inv_model_view_proj", glm::inverse(camera.viewProj * model));
  p.set("u_world_to_object_normal", glm::transpose(glm::mat3(model)));
  if (turbulenceGrid != 0) glBindTextureUnit(kTurbulenceGridUnit, turbulenceGrid);
}

void AlbedoPass::compileAll() {
  for (NoiseBasis b : {NoiseBasis::Value, NoiseBasis::Perlin})
    for (PatternMapping p : {PatternMapping::Planar, PatternMapping::Triplanar, PatternMapping::Solid}) {
      Material m;
      m.basis = b;
      m.mapping = p;
      programs_.get(patternDefines(m, 0));
      if (turbulenceGridDimensions(m) > 0) programs_.get(patternDefines(m, 1));  // any nonzero grid
    }
  for (VeinModel v : {VeinModel::Network, VeinModel::Breccia}) {  // solid whatever the mapping
    Material m;
    m.vein_model = v;
    programs_.get(patternDefines(m, 0));
    programs_.get(patternDefines(m, 1));
  }
}

void AlbedoPass::resize(int width, int height, GLuint depthTexture) {
  if (width != width_ || height != height_ || !fbo_) {
    width_ = width;
    height_ = height;
    albedo_ = gl::makeTexture2D(GL_RGBA8, width, height, GL_NEAREST);
    fbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, albedo_.id(), 0);
  }
  // Borrowed: attached every time, never compared by name (gl::Borrowed).
  gl::attachSurfaceDepth(fbo_.id(), depthTexture);
}

void AlbedoPass::run(GLuint depthTexture, GLuint normalTexture, const glm::mat4& model, const CameraMatrices& camera,
                     const Material& material, GLuint turbulenceGrid, const ScreenRect& rect) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::setSurfaceOnlyScreenPassState();
  const float zero[4] = {0, 0, 0, 0};
  gl::clearFramebuffer(fbo_.id(), GL_COLOR, 0, zero);
  scissorTo(rect);
  const GLuint textures[] = {depthTexture, normalTexture};
  glBindTextures(shader::UNIT_ALBEDO_DEPTH, 2, textures);
  const gl::Program& p = programs_.get(patternVariantKey(material, turbulenceGrid),
                                       [&] { return patternDefines(material, turbulenceGrid); });
  setPatternUniforms(p, model, camera, turbulenceGrid);
  uploadMaterialUniforms(p, material);
  gl::drawFullscreenTriangle(p.id(), emptyVao_.id());
  scissorOff();
  timer_.end();
}

}  // namespace marble
