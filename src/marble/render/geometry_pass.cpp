#include "marble/render/geometry_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "marble/noise/pattern_uniforms.h"

namespace marble {

GeometryPass::GeometryPass(const ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "geometry.frag.glsl"}}) {
  programs_.get(variantFor(Material{}));  // the default material's, so a broken shader shows at once
}

std::vector<std::string> GeometryPass::variantFor(const Material& m) {
  return {"PAT_BASIS " + std::to_string(static_cast<int>(m.basis)),
          "PAT_MAPPING " + std::to_string(static_cast<int>(m.mapping))};
}

void GeometryPass::compileAll() {
  for (NoiseBasis b : {NoiseBasis::Value, NoiseBasis::Perlin})
    for (PatternMapping p : {PatternMapping::Planar, PatternMapping::Triplanar, PatternMapping::Solid}) {
      Material m;
      m.basis = b;
      m.mapping = p;
      programs_.get(variantFor(m));
    }
}

void GeometryPass::resize(int width, int height) {
  if (width == width_ && height == height_ && fbo_) return;
  width_ = width;
  height_ = height;
  albedo_ = gl::makeTexture2D(GL_RGBA8, width, height, GL_NEAREST);
  normal_ = gl::makeTexture2D(GL_RG16_SNORM, width, height, GL_NEAREST);
  depth_ = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, albedo_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, normal_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo_.id(), 2, bufs);
}

void GeometryPass::run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera,
                       const Material& material) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::setMeshPassState();
  const float zero[4] = {0, 0, 0, 0};
  const float one = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, zero);
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
  const gl::Program& program = programs_.get(variantFor(material));
  program.set("u_model", model);
  program.set("u_view_proj", camera.viewProj);
  program.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  applyPatternUniforms(program.id(), material);
  glUseProgram(program.id());
  mesh.draw();
  timer_.end();
}

}  // namespace marble
