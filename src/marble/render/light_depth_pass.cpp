#include "marble/render/light_depth_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace marble {

LightDepthPass::LightDepthPass(const ShaderLibrary& shaders, int size)
    : size_(size),
      program_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "light_depth.frag.glsl"}}),
      // Nearest, not linear: at the object's silhouette seen from the light, blending a surface
      // distance with the "nothing hit" clear value would invent huge entry distances, hence
      // zero thickness and light leaking through past the terminator.
      // RG: the distance, and the cosine at which the light enters there (light_depth.frag.glsl).
      distance_(gl::makeTexture2D(GL_RG32F, size, size, GL_NEAREST)),
      depth_(gl::makeTexture2D(GL_DEPTH_COMPONENT32F, size, size, GL_LINEAR)),
      fbo_(gl::Framebuffer::create()) {
  // Shadows read the depth with hardware comparison and bilinear filtering (PCF).
  glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, distance_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
}

void LightDepthPass::run(const GpuMesh& mesh, const glm::mat4& model, const LightMatrices& light) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size_, size_);
  gl::setMeshPassState();  // both faces: meshes with holes must still block the light
  // "Nothing hit": a distance beyond every surface, no light entering.
  const float farValue[4] = {light.far + 1e3f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, farValue);
  const float one = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
  program_.set("u_model", model);
  program_.set("u_view_proj", light.viewProj);
  program_.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  program_.set("u_light_pos", light.position);
  program_.set("u_light_dir", light.direction);
  program_.set("u_light_directional", light.directional ? 1 : 0);
  glUseProgram(program_.id());
  mesh.draw();
  timer_.end();
}

}  // namespace marble
