#include "marble/render/renderer.h"

#include <algorithm>
#include <cstring>

namespace marble {

struct Renderer::Passes {
  explicit Passes(const ShaderLibrary& s) : lightDepth(s), geometry(s), lighting(s), blur(s), post(s), floor(s) {}
  LightDepthPass lightDepth;
  GeometryPass geometry;
  LightingPass lighting;
  SubsurfaceBlurPass blur;
  PostPass post;
  FloorPass floor;
};

bool samePattern(const Material& a, const Material& b) {
  return a.seed == b.seed && a.resolution == b.resolution && a.basis == b.basis && a.mapping == b.mapping &&
         a.x_period == b.x_period && a.y_period == b.y_period && a.z_period == b.z_period &&
         a.turb_power == b.turb_power && a.turb_size == b.turb_size && a.pattern_scale == b.pattern_scale &&
         a.base_color == b.base_color && a.vein_color == b.vein_color && a.vein2_color == b.vein2_color &&
         a.vein_sharpness == b.vein_sharpness && a.vein2_amount == b.vein2_amount;
}

namespace {
bool sameLightingInputs(const Scene& a, const Scene& b) {
  return a.material == b.material && a.mm_per_unit == b.mm_per_unit && a.light.type == b.light.type &&
         a.light.position == b.light.position && a.light.color == b.light.color &&
         a.light.intensity == b.light.intensity && a.camera.position == b.camera.position &&
         a.camera.target == b.camera.target && a.camera.up == b.camera.up && a.camera.fov_y_deg == b.camera.fov_y_deg &&
         a.render.mode == b.render.mode && a.render.environment == b.render.environment &&
         a.render.environment_intensity == b.render.environment_intensity &&
         a.render.environment_rotation_deg == b.render.environment_rotation_deg;
}
bool sameMatrix(const glm::mat4& a, const glm::mat4& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }
}  // namespace

Renderer::Renderer(ShaderLibrary shaders) : shaders_(std::move(shaders)), passes_(std::make_unique<Passes>(shaders_)) {
  // llvmpipe reports the context's age, not the elapsed time, for the first GL_TIME_ELAPSED
  // query of a context: spend it on an empty one.
  PassTimer warmup;
  warmup.begin();
  warmup.end();
  warmup.waitMilliseconds();
}
Renderer::~Renderer() = default;

void Renderer::setMesh(const Mesh& mesh) {
  mesh_.emplace(mesh);
  invalidate();
}

void Renderer::setEnvironmentMap(const PrefilteredEnvironment& environment) {
  environment_.emplace(environment);
  lightingValid_ = false;
}

void Renderer::clearEnvironmentMap() {
  environment_.reset();
  lightingValid_ = false;
}

void Renderer::reloadShaders() {
  auto fresh = std::make_unique<Passes>(shaders_);  // throws on error; old passes stay
  passes_ = std::move(fresh);
  invalidate();
}

void Renderer::render(const Scene& scene, const glm::mat4& model, GLuint targetFbo, int width, int height) {
  if (!mesh_ || width <= 0 || height <= 0) return;
  const CameraMatrices camera = cameraMatrices(scene.camera, static_cast<float>(width) / static_cast<float>(height));
  times_.lightDepthRan = times_.geometryRan = false;
  if (scene.render.mode == RenderMode::Floor) {
    passes_->floor.run(*mesh_, model, camera, scene.light.position, scene.material.base_color, scene.render.background,
                       targetFbo, width, height);
    return;
  }
  const LightMatrices light = lightMatrices(scene.light);
  if (!lightValid_ || !sameMatrix(light.viewProj, lastLight_.viewProj) || !sameMatrix(model, lastModel_)) {
    passes_->lightDepth.run(*mesh_, model, light);
    lightValid_ = true;
    times_.lightDepthRan = true;
  }
  passes_->geometry.resize(width, height);
  if (!geometryValid_ || !sameMatrix(camera.viewProj, lastCamera_.viewProj) || !sameMatrix(model, lastModel_) ||
      !samePattern(scene.material, lastMaterial_)) {
    passes_->geometry.run(*mesh_, model, camera, scene.material);
    geometryValid_ = true;
    times_.geometryRan = true;
  }
  lastLight_ = light;
  lastCamera_ = camera;
  lastModel_ = model;
  lastMaterial_ = scene.material;
  const LightingInputs in{passes_->geometry.albedoTexture(), passes_->geometry.normalTexture(),
                          passes_->geometry.depthTexture(), passes_->lightDepth.distanceTexture(),
                          passes_->lightDepth.depthTexture()};
  // Lighting and blur depend on everything but the exposure and the background (post-only).
  Scene lightingScene = scene;
  lightingScene.render.exposure = 0.0f;
  lightingScene.render.background = glm::vec3(0.0f);
  const bool lightingCurrent = lightingValid_ && !times_.lightDepthRan && !times_.geometryRan && width == lastWidth_ &&
                               height == lastHeight_ && sameLightingInputs(lightingScene, lastLightingScene_);
  times_.lightingRan = !lightingCurrent;
  if (!lightingCurrent) {
    passes_->lighting.resize(width, height);
    const float lightTexelWorld = 2.0f * kBoundingRadius / static_cast<float>(passes_->lightDepth.size());
    passes_->lighting.run(in, camera, light, scene.light, scene.material, scene, lightTexelWorld,
                          environment_ ? &*environment_ : nullptr);
    finalHdrTexture_ = passes_->lighting.hdrTexture();
    finalHdrFbo_ = passes_->lighting.fbo();
    if (scene.render.mode == RenderMode::Marble) {
      passes_->blur.resize(width, height);
      passes_->blur.run({passes_->lighting.enteringTexture(), passes_->lighting.hdrTexture(),
                         passes_->geometry.albedoTexture(), passes_->geometry.depthTexture()},
                        camera, scene, height);
      finalHdrTexture_ = passes_->blur.resultTexture();
      finalHdrFbo_ = passes_->blur.resultFbo();
    }
    lightingValid_ = true;
    lastLightingScene_ = lightingScene;
    lastWidth_ = width;
    lastHeight_ = height;
  }
  passes_->post.run(finalHdrTexture_, passes_->geometry.depthTexture(), scene.render, targetFbo, width, height);
}

PassTimes Renderer::passTimes(bool wait) {
  auto get = [wait](PassTimer& t) { return wait ? t.waitMilliseconds() : t.milliseconds(); };
  times_.lightDepthMs = get(passes_->lightDepth.timer());
  times_.geometryMs = get(passes_->geometry.timer());
  times_.lightingMs = get(passes_->lighting.timer());
  times_.subsurfaceBlurMs = get(passes_->blur.timer());
  times_.postMs = get(passes_->post.timer());
  times_.floorMs = get(passes_->floor.timer());
  return times_;
}

size_t Renderer::glBytes() const {
  return passes_->lightDepth.bytes() + passes_->geometry.bytes() + passes_->lighting.bytes() + passes_->blur.bytes() +
         (mesh_ ? mesh_->bytes() : 0) + (environment_ ? environment_->bytes() : 0);
}

ImageRGBF Renderer::readHdr() const {
  const GLuint fbo = finalHdrFbo_;
  GLint w = 0, h = 0;
  glGetNamedFramebufferAttachmentParameteriv(fbo, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &w);
  const auto texture = static_cast<GLuint>(w);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
  ImageRGBF img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
  std::vector<float> rows(img.pixels.size());
  glNamedFramebufferReadBuffer(fbo, GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, rows.data());
  const size_t row = static_cast<size_t>(w) * 3;
  for (int y = 0; y < h; ++y)
    std::copy_n(rows.begin() + static_cast<ptrdiff_t>((h - 1 - y) * row), row, img.pixels.begin() + static_cast<ptrdiff_t>(y * row));
  return img;
}

}  // namespace marble
