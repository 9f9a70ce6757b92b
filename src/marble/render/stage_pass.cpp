#include "marble/render/stage_pass.h"

#include <cmath>
#include <cstring>

#include "marble/render/frame_uniforms.h"
#include "marble/render/shader_constants.h"

namespace marble {

namespace {
// A directional light from below: the light-depth pass then stores, per texel of an orthographic
// view covering the bounding sphere from below, dot(p, +Y) of the first surface -- its height.
LightMatrices fromBelow() {
  Light below;
  below.type = LightType::Directional;
  below.position = glm::vec3(0.0f, -1.0f, 0.0f);
  return lightMatrices(below);
}
constexpr int kBottomMapSize = 256;  // the contact shadow is soft: 0.014 units per texel
}  // namespace

bool sceneHasStage(const Scene& scene) {
  return scene.render.mode == RenderMode::Marble && (scene.render.ground || scene.render.backdrop);
}

StagePass::StagePass(const ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "stage.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()),
      bottom_(shaders, kBottomMapSize),
      bottomMatrices_(fromBelow()) {}

void StagePass::updateBottomMap(const GpuMesh& mesh, const glm::mat4& model) {
  if (bottomValid_ && std::memcmp(&model, &bottomModel_, sizeof model) == 0) return;
  bottom_.run(mesh, model, bottomMatrices_);
  bottomModel_ = model;
  bottomValid_ = true;
}

void StagePass::run(const Scene& scene, const CameraMatrices& camera, const LightMatrices& light, float lightTexelWorld,
                    const EnvironmentMap* environment, GLuint depth, GLuint lightShadow, float groundY,
                    GLuint targetFbo, int width, int height, bool lumaAlpha) {
  const RenderSettings& r = scene.render;
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  const GLenum first = GL_COLOR_ATTACHMENT0;
  glNamedFramebufferDrawBuffers(targetFbo, 1, &first);
  glViewport(0, 0, width, height);
  gl::setScreenPassState();
  const int envKind = environmentKind(r, environment);
  const gl::Program& p = programs_.get(static_cast<uint32_t>(envKind), [&] { return std::vector<std::string>{environmentDefine(r, environment)}; });
  setFrameUniforms(p, camera, light, scene.light, lightTexelWorld);
  setEnvironmentUniforms(p, r, environment);
  setStudioBlurUniform(p, r.backdrop_blur);
  const bool envOn = r.environment == Environment::Studio || envKind == kEnvMap;
  p.set("u_env_on", envOn ? 1 : 0);
  p.set("u_luma_alpha", lumaAlpha ? 1 : 0);
  p.set("u_exposure_scale", std::exp2(r.exposure));
  p.set("u_background", glm::clamp(r.background, 0.0f, 1.0f));
  p.set("u_backdrop", r.backdrop ? 1 : 0);
  p.set("u_backdrop_blur", r.backdrop_blur);
  p.set("u_ground", r.ground ? 1 : 0);
  p.set("u_ground_y", groundY);
  p.set("u_bottom_view_proj", bottomMatrices_.viewProj);
  glBindTextureUnit(shader::UNIT_SURFACE_DEPTH, depth);
  glBindTextureUnit(shader::UNIT_STAGE_LIGHT_SHADOW, lightShadow);
  glBindTextureUnit(shader::UNIT_STAGE_BOTTOM_DISTANCE, bottom_.distanceTexture());
  gl::drawFullscreenTriangle(p.id(), emptyVao_.id());
  timer_.end();
}

}  // namespace marble
