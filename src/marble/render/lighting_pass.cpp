#include "marble/render/lighting_pass.h"

namespace marble {

LightingPass::LightingPass(const ShaderLibrary& shaders)
    : program_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "lighting.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {}

void LightingPass::resize(int width, int height) {
  if (width == width_ && height == height_ && fbo_) return;
  width_ = width;
  height_ = height;
  hdr_ = gl::makeTexture2D(GL_RGBA16F, width, height, GL_LINEAR);
  entering_ = gl::makeTexture2D(GL_RGBA16F, width, height, GL_LINEAR);
  fbo_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, hdr_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, entering_.id(), 0);
  const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo_.id(), 2, bufs);
}

void LightingPass::setEnvironment(const RenderSettings& settings, const EnvironmentMap* environment) {
  const auto& p = program_;
  const bool map = settings.environment == Environment::Map && environment;
  const bool lit = settings.environment == Environment::Studio || map;
  p.set("u_env_intensity", lit ? settings.environment_intensity : 0.0f);
  p.set("u_env_kind", map ? 1 : 0);
  if (map) {
    environment->setUniforms(p, settings.environment_rotation_deg);
    glBindTextureUnit(5, environment->texture());
  }
}

// sigma_tr = sqrt(3 sigma_a (sigma_a + sigma_s')) per channel (Jensen et al. 2001, eq. 5).
static glm::vec3 transportCoefficient(const Material& m) {
  return glm::sqrt(3.0f * m.sigma_a_mm * (m.sigma_a_mm + m.sigma_s_mm));
}

void LightingPass::run(const LightingInputs& in, const CameraMatrices& camera, const LightMatrices& lightM,
                       const Light& light, const Material& m, const Scene& scene, float lightTexelWorld,
                       const EnvironmentMap* environment) {
  const RenderSettings& settings = scene.render;
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  gl::setScreenPassState();
  const GLuint textures[] = {in.albedo, in.normal, in.depth, in.lightDistance, in.lightDepth};
  glBindTextures(0, 5, textures);
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
  p.set("u_sigma_t", m.sigma_t);
  p.set("u_k_sss", m.k_sss);
  p.set("u_k_schlick", m.k_schlick);
  p.set("u_metalness", m.metalness);
  p.set("u_reflectance_first", m.order == ShadingOrder::ReflectanceFirst ? 1 : 0);
  p.set("u_schlick_hn", m.schlick_cos == SchlickCosine::HdotN ? 1 : 0);
  p.set("u_shininess", m.shininess);
  p.set("u_oren_nayar_sigma", m.oren_nayar_sigma);
  p.set("u_mode", static_cast<int>(settings.mode));
  p.set("u_mm_per_unit", scene.mm_per_unit);
  p.set("u_sigma_tr_mm", transportCoefficient(m));
  p.set("u_ior", m.ior);
  p.set("u_roughness", m.roughness);
  p.set("u_translucency", m.translucency);
  setEnvironment(settings, environment);
  p.set("u_light_texel_world", lightTexelWorld);
  glUseProgram(p.id());
  glBindVertexArray(emptyVao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  timer_.end();
}

}  // namespace marble
