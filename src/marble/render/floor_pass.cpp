#include "marble/render/floor_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace marble {

FloorPass::FloorPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "flat.frag.glsl"}}) {}

void FloorPass::run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera, const glm::vec3& lightPos,
                    const glm::vec3& color, const glm::vec3& background, GLuint targetFbo, int width, int height) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glViewport(0, 0, width, height);
  gl::setMeshPassState();
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  program_.set("u_model", model);
  program_.set("u_view_proj", camera.viewProj);
  program_.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  program_.set("u_light_pos", lightPos);
  program_.set("u_color", color);
  glUseProgram(program_.id());
  mesh.draw();
  timer_.end();
}

}  // namespace marble
