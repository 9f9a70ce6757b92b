#include "marble/render/geometry_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "marble/gl/checked_calls.h"

namespace marble {

GeometryPass::GeometryPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "geometry.frag.glsl"}}) {}

void GeometryPass::resize(int width, int height) {
  if (width == width_ && height == height_ && fbo_) return;
  width_ = width;
  height_ = height;
  normals_ = gl::makeTexture2D(GL_RGBA16_SNORM, width, height, GL_NEAREST);
  depth_ = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, normals_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
}

void GeometryPass::run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera,
                       bool validReflection) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::setMeshPassState();
  const float zero[4] = {0, 0, 0, 0};
  const float one = 1.0f;
  gl::clearFramebuffer(fbo_.id(), GL_COLOR, 0, zero);
  gl::clearFramebuffer(fbo_.id(), GL_DEPTH, 0, &one);
  program_.set("u_model", model);
  program_.set("u_view_proj", camera.viewProj);
  program_.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  program_.set("u_camera_position", camera.position);
  program_.set("u_valid_reflection", validReflection ? 1 : 0);
  glUseProgram(program_.id());
  mesh.draw();
  timer_.end();
}

}  // namespace marble
