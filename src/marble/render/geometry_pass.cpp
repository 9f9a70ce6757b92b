#include "marble/render/geometry_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "marble/gl/checked_calls.h"
#include "marble/render/face_culling.h"

namespace marble {

GeometryPass::GeometryPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "geometry.frag.glsl"}}) {}

void GeometryPass::resize(int width, int height) {
  if (width == width_ && height == height_ && fbo_) return;
  width_ = width;
  height_ = height;
  normal_ = gl::makeTexture2D(GL_RG16_SNORM, width, height, GL_NEAREST);
  specularNormal_ = gl::makeTexture2D(GL_RGBA16_SNORM, width, height, GL_NEAREST);
  depth_ = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, normal_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, specularNormal_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  drawBuffersSet_ = false;  // a new framebuffer draws to attachment 0 only
}

void GeometryPass::run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera,
                       bool validReflection) {
  timer_.begin();
  // The bent normal only where it is read (marble mode); otherwise its attachment is not drawn.
  // Framebuffer state: set when the framebuffer is new or the mode changes, not every frame.
  if (!drawBuffersSet_ || validReflection != validReflection_) {
    const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, validReflection ? GLenum{GL_COLOR_ATTACHMENT1} : GLenum{GL_NONE}};
    glNamedFramebufferDrawBuffers(fbo_.id(), 2, drawBuffers);
    drawBuffersSet_ = true;
  }
  validReflection_ = validReflection;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::setMeshPassState();
  const float zero[4] = {0, 0, 0, 0};
  const float one = 1.0f;
  gl::clearFramebuffer(fbo_.id(), GL_COLOR, 0, zero);
  if (validReflection) gl::clearFramebuffer(fbo_.id(), GL_COLOR, 1, zero);
  gl::clearFramebuffer(fbo_.id(), GL_DEPTH, 0, &one);
  program_.set("u_model", model);
  program_.set("u_view_proj", camera.viewProj);
  program_.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  program_.set("u_camera_position", camera.position);
  program_.set("u_valid_reflection", validReflection ? 1 : 0);
  glUseProgram(program_.id());
  hiddenFaceDraw_.prepare(cullsHiddenFaces_, cullsOnCpu_, mesh, camera.viewProj * model, width_, height_);
  hiddenFaceDraw_.draw(mesh);
  glDisable(GL_CULL_FACE);  // the other passes' state (gl::set*PassState) assumes it off
  timer_.end();
}

}  // namespace marble
