#include "marble/render/floor_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "marble/gl/checked_calls.h"

namespace marble {

FloorPass::FloorPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "flat.frag.glsl"}}) {}

void FloorPass::resize(int width, int height) {
  if (width == width_ && height == height_ && fbo_) return;
  width_ = width;
  height_ = height;
  color_ = gl::makeTexture2D(GL_RGBA8, width, height, GL_NEAREST);
  depth_ = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
}

void FloorPass::run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera, const glm::vec3& lightPos,
                    const glm::vec3& color, const glm::vec3& background, GLuint targetFbo, int width, int height) {
  resize(width, height);
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width, height);
  gl::setMeshPassState();
  const glm::vec4 clear(background, 1.0f);
  const float one = 1.0f;
  gl::clearFramebuffer(fbo_.id(), GL_COLOR, 0, &clear.x);
  gl::clearFramebuffer(fbo_.id(), GL_DEPTH, 0, &one);
  program_.set("u_model", model);
  program_.set("u_view_proj", camera.viewProj);
  program_.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  program_.set("u_light_pos", lightPos);
  program_.set("u_color", color);
  glUseProgram(program_.id());
  mesh.draw();
  gl::blitFramebuffer(fbo_.id(), targetFbo, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  timer_.end();
}

}  // namespace marble
