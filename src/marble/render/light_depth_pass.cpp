#include "marble/render/light_depth_pass.h"

#include <algorithm>

#include <glm/gtc/matrix_inverse.hpp>

#include "marble/gl/checked_calls.h"
#include "marble/render/face_culling.h"

namespace marble {
namespace {

// The uniforms both of the pass's programs (light_depth and light_layers) take to place the mesh
// in the light's view.
void setLightViewUniforms(gl::Program& program, const glm::mat4& model, const LightMatrices& light) {
  program.set("u_model", model);
  program.set("u_view_proj", light.viewProj);
  program.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  program.set("u_light_pos", light.position);
  program.set("u_light_dir", light.direction);
  program.set("u_light_directional", light.directional ? 1 : 0);
}

}  // namespace

LightDepthPass::LightDepthPass(const ShaderLibrary& shaders, int size)
    : program_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "light_depth.frag.glsl"}}),
      layersProgram_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "light_layers.frag.glsl"}}),
      full_(size) {}

void LightDepthPass::setMapSize(int size) {
  size = std::clamp(size, 1, full_.size);
  if (size == maps().size) return;
  if (size == full_.size) {
    reducedInUse_ = false;
    return;
  }
  if (!reduced_ || reduced_->size != size) reduced_.emplace(size);
  reducedInUse_ = true;
}

void LightDepthPass::run(const GpuMesh& mesh, const glm::mat4& model, const LightMatrices& light) {
  timer_.begin();
  LightMaps& m = maps();
  glBindFramebuffer(GL_FRAMEBUFFER, m.fbo.id());
  glViewport(0, 0, m.size, m.size);
  // Both faces where the mesh may show either to the light (a mesh with holes must still block
  // it); else only those facing it: the nearest surface is the same (face_culling.h).
  gl::setMeshPassState();
  // The triangles GL culls are dropped before it where GL rasterizes in software (face_culling.h,
  // HiddenFaceDraw; GpuMesh::cullsOnCpu), chosen once for both maps at the smaller one's size.
  const int smaller = std::min(m.size, m.bounceSize);
  hiddenFaceDraw_.prepare(cullsHiddenFaces_, true, mesh, light.viewProj * model, smaller, smaller);
  // "Nothing hit": a distance beyond every surface, no light entering.
  const float farValue[4] = {light.far + 1e3f, 0.0f, 0.0f, 0.0f};
  gl::clearFramebuffer(m.fbo.id(), GL_COLOR, 0, farValue);
  const float one = 1.0f;
  gl::clearFramebuffer(m.fbo.id(), GL_DEPTH, 0, &one);
  setLightViewUniforms(program_, model, light);
  glUseProgram(program_.id());
  hiddenFaceDraw_.draw(mesh);
  // The reflective shadow map: nothing there, nothing re-emitted (w = 0).
  glBindFramebuffer(GL_FRAMEBUFFER, m.bounceFbo.id());
  glViewport(0, 0, m.bounceSize, m.bounceSize);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  gl::clearFramebuffer(m.bounceFbo.id(), GL_COLOR, 1, zero);
  gl::clearFramebuffer(m.bounceFbo.id(), GL_COLOR, 2, zero);
  gl::clearFramebuffer(m.bounceFbo.id(), GL_DEPTH, 0, &one);
  hiddenFaceDraw_.draw(mesh);
  glDisable(GL_CULL_FACE);  // the layers draw both faces, and the other passes assume it off
  glGenerateTextureMipmap(m.bouncePosition.id());
  glGenerateTextureMipmap(m.bounceNormal.id());
  // The entry and exit layers (light_layers.frag.glsl): every fragment of both faces, each channel
  // keeping its nearest by MIN blending (no depth test: the nearest exit lies behind the nearest
  // entry). The blend and depth state is put back as the mesh passes left it.
  glBindFramebuffer(GL_FRAMEBUFFER, m.layersFbo.id());
  glViewport(0, 0, m.layersSize, m.layersSize);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendEquation(GL_MIN);
  const float none[4] = {kNoLayer, kNoLayer, 0.0f, 0.0f};
  gl::clearFramebuffer(m.layersFbo.id(), GL_COLOR, 0, none);
  setLightViewUniforms(layersProgram_, model, light);
  layersProgram_.set("u_none", kNoLayer);
  layersProgram_.set("u_outward", mesh.woundInward() ? -1.0f : 1.0f);
  glUseProgram(layersProgram_.id());
  mesh.draw();
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  timer_.end();
}

}  // namespace marble
