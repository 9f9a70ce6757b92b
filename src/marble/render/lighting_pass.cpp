#include "marble/render/lighting_pass.h"

namespace marble {

LightingPass::LightingPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "lighting.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {}

void LightingPass::run(const LightingInputs& in, const CameraMatrices& camera, const LightMatrices& lightM,
                       const Light& light, const Material& m, const RenderSettings& settings, GLuint targetFbo,
                       int width, int height) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  const GLuint textures[] = {in.albedo, in.normal, in.depth, in.lightDistance};
  glBindTextures(0, 4, textures);
  const auto& p = program_;
  p.set("u_inv_view_proj", camera.invViewProj);
  p.set("u_camera_pos", camera.position);
  p.set("u_camera_near_far", glm::vec2(camera.near, camera.far));
  p.set("u_light_view_proj", lightM.viewProj);
  p.set("u_light_pos", lightM.position);
  p.set("u_light_dir", lightM.direction);
  p.set("u_light_directional", lightM.directional ? 1 : 0);
  p.set("u_light_near_far", glm::vec2(lightM.near, lightM.far));
  p.set("u_light_radiance", light.color * light.intensity);
  p.set("u_background", settings.background);
  p.set("u_sigma_t", m.sigma_t);
  p.set("u_k_sss", m.k_sss);
  p.set("u_k_schlick", m.k_schlick);
  p.set("u_metalness", m.metalness);
  p.set("u_reflectance_first", m.order == ShadingOrder::ReflectanceFirst ? 1 : 0);
  p.set("u_schlick_hn", m.schlick_cos == SchlickCosine::HdotN ? 1 : 0);
  p.set("u_shininess", m.shininess);
  p.set("u_oren_nayar_sigma", m.oren_nayar_sigma);
  p.set("u_mode", static_cast<int>(settings.mode));
  glUseProgram(p.id());
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  timer_.end();
}

}  // namespace marble
