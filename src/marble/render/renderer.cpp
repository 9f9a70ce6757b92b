#include "marble/render/renderer.h"

#include <algorithm>
#include <cstring>

#include "marble/mesh/mesh_optimize.h"
#include "marble/render/mesh_detail.h"
#include "marble/scene/material_params.h"

namespace marble {

struct Renderer::Passes {
  explicit Passes(const ShaderLibrary& s)
      : lightDepth(s), geometry(s), albedo(s), blurDepth(s), lighting(s), blur(s), post(s), floor(s), fxaa(s), stage(s) {}
  LightDepthPass lightDepth;
  GeometryPass geometry;
  AlbedoPass albedo;
  BlurDepthPass blurDepth;
  LightingPass lighting;
  SubsurfaceBlurPass blur;
  PostPass post;
  FloorPass floor;
  FxaaPass fxaa;
  StagePass stage;
};

void Renderer::invalidateStage() { passes_->stage.invalidateBottomMap(); }

namespace {
// What the pattern's evaluation reads (the albedo pass, or `marble`'s post pass evaluating it):
// the pattern, colour and vein-model groups.
const GroupSet kAlbedoGroups = groupsRead(kAlbedoPassBit, RenderMode::Albedo);

bool sameView(const Scene& a, const Scene& b) {
  return a.light.type == b.light.type && a.light.position == b.light.position && a.light.color == b.light.color &&
         a.light.intensity == b.light.intensity && a.camera.position == b.camera.position &&
         a.camera.target == b.camera.target && a.camera.up == b.camera.up &&
         a.camera.fov_y_deg == b.camera.fov_y_deg && a.render.mode == b.render.mode &&
         a.render.environment == b.render.environment &&
         a.render.environment_intensity == b.render.environment_intensity &&
         a.render.subsurface_resolution == b.render.subsurface_resolution &&
         a.render.environment_rotation_deg == b.render.environment_rotation_deg;
}
// What the lighting pass (and, for `marble`, the subsurface blur) reads besides the G-buffer,
// the light's map and, outside `marble`, the albedo texture: the groups of the parameters they
// read in this mode (material_params.cpp says which). For `marble` that is the light entering
// the stone (the scattering group) -- not the albedo or the gloss, which the post pass applies.
bool sameLightingInputs(const Scene& a, const Scene& b) {
  if (!sameView(a, b)) return false;
  return a.mm_per_unit == b.mm_per_unit &&
         sameGroups(a.material, b.material, groupsRead(kLightingPassBit | kBlurPassBit, a.render.mode));
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
  cpuMesh_ = mesh;
  if (drawOrderOptimized_) optimizeDrawOrder(cpuMesh_);
  mesh_.emplace(cpuMesh_);
  meshCells_ = OccupancyGrid(cpuMesh_);
  aaSpansWidth_ = 0;  // made anew for this mesh
  interactionMesh_.reset();
  interactionIsFull_ = false;
  makeLightProxy();
  invalidate();
}

void Renderer::makeLightProxy() {
  lightMesh_.reset();
  lightProxyMesh_ = Mesh();
  lightProxyErrorUnits_ = 0.0f;
  lightProxyJob_.reset();  // a copy still being made for an earlier mesh is abandoned
  const size_t triangles = cpuMesh_.triangleCount();
  if (!lightProxyEnabled_ || triangles <= kLightProxyMinTriangles) return;
  const auto target = std::min(kLightProxyMaxTriangles,
                               static_cast<size_t>(static_cast<double>(triangles) * kLightProxyTriangleFraction));
  const float maxError = lightProxyMaxErrorUnits(passes_->lightDepth.size());
  if (lightProxyInBackground_) {
    lightProxyJob_.emplace(cpuMesh_, target, maxError);
    return;
  }
  useLightProxy(simplifiedMesh(cpuMesh_, target, maxError));
}

void Renderer::useLightProxy(SimplifiedMesh proxy) {
  if (proxy.mesh.triangleCount() >= cpuMesh_.triangleCount()) return;  // nothing could be collapsed
  lightProxyErrorUnits_ = proxy.errorUnits;
  lightMesh_.emplace(proxy.mesh);
  lightProxyMesh_ = std::move(proxy.mesh);
}

void Renderer::adoptLightProxy(bool wait) {
  if (!lightProxyJob_ || (!wait && !lightProxyJob_->ready())) return;
  SimplifiedMesh proxy = lightProxyJob_->take();
  lightProxyJob_.reset();
  useLightProxy(std::move(proxy));
  interactionMesh_.reset();  // made from the proxy from now on
  interactionIsFull_ = false;
  invalidate();  // every pass, as after setMesh: the next frame is a fresh renderer's
}

void Renderer::setLightProxyEnabled(bool enabled) {
  if (enabled == lightProxyEnabled_) return;
  lightProxyEnabled_ = enabled;
  if (mesh_) makeLightProxy();
  interactionMesh_.reset();  // it is made from the proxy: made again at its next use
  interactionIsFull_ = false;
  lightValid_ = lightingValid_ = outputValid_ = false;
}

size_t Renderer::lightTriangleCount() const {
  if (!mesh_) return 0;
  return lightMesh().triangleCount();
}

const GpuMesh& Renderer::cameraMesh() {
  if (detail_ == MeshDetail::Full || !mesh_) return *mesh_;
  if (!interactionMesh_ && !interactionIsFull_) {
    if (cpuMesh_.triangleCount() <= kInteractionTriangles) {
      interactionIsFull_ = true;
    } else if (lightProxyJob_) {
      return *mesh_;  // made from the proxy once it is there (from the full mesh: seconds)
    } else {
      // From the light's proxy where there is one: the simplifier's cost grows with what it
      // starts from (1.6 M triangles: 1.7 s from the mesh, far less from the proxy).
      const Mesh& from = lightProxyMesh_.indices.empty() ? cpuMesh_ : lightProxyMesh_;
      interactionMesh_.emplace(simplifiedMesh(from, kInteractionTriangles, kInteractionMaxErrorUnits).mesh);
    }
  }
  return interactionMesh_ ? *interactionMesh_ : *mesh_;
}

void Renderer::setMeshDetail(MeshDetail detail) {
  if (detail == detail_) return;
  detail_ = detail;
  // The camera's passes re-run with the other mesh (the interaction copy may be the full mesh
  // itself: re-running then costs one frame and changes nothing).
  geometryValid_ = outputValid_ = false;
}

size_t Renderer::interactionTriangleCount() {
  if (!mesh_) return 0;
  const MeshDetail saved = detail_;
  detail_ = MeshDetail::Interaction;
  const size_t n = cameraMesh().triangleCount();
  detail_ = saved;
  return n;
}

void Renderer::setEnvironmentMap(const PrefilteredEnvironment& environment) {
  environment_.emplace(environment);
  lightingValid_ = outputValid_ = false;
}

void Renderer::clearEnvironmentMap() {
  environment_.reset();
  lightingValid_ = outputValid_ = false;
}

void Renderer::reloadShaders() {
  auto fresh = std::make_unique<Passes>(shaders_);  // throws on error; old passes stay
  // Every specialized program now, not at its first use: an error must show here, while
  // the previous programs are still in use.
  fresh->albedo.compileAll();
  fresh->lighting.compileAll();
  fresh->post.compileAll();
  passes_ = std::move(fresh);
  invalidate();
}

void Renderer::render(const Scene& scene, const glm::mat4& model, GLuint targetFbo, int width, int height) {
  adoptLightProxy(false);
  if (!mesh_ || width <= 0 || height <= 0) return;
  const CameraMatrices camera = cameraMatrices(scene.camera, static_cast<float>(width) / static_cast<float>(height));
  times_.lightDepthRan = times_.geometryRan = times_.albedoRan = times_.lightingRan = times_.blurDepthRan = false;
  times_.postRan = times_.fxaaRan = times_.floorRan = times_.stageRan = false;
  times_.diffuseSource = -1;
  outputValid_ = true;
  lastOutput_ = OutputKey{scene, model, targetFbo, width, height};
  if (scene.render.mode == RenderMode::Floor) {
    passes_->floor.run(cameraMesh(), model, camera, scene.light.position, scene.material.base_color, scene.render.background,
                       targetFbo, width, height);
    times_.floorRan = true;
    return;
  }
  const LightMatrices light = lightMatrices(scene.light);
  const bool modelMoved = !sameMatrix(model, lastModel_);
  if (!lightValid_ || !sameMatrix(light.viewProj, lastLight_.viewProj) || modelMoved) {
    passes_->lightDepth.run(lightMesh(), model, light);
    lightValid_ = true;
    times_.lightDepthRan = true;
  }
  passes_->geometry.resize(width, height);
  const bool viewMoved = !geometryValid_ || !sameMatrix(camera.viewProj, lastCamera_.viewProj) || modelMoved ||
                         width != lastWidth_ || height != lastHeight_;
  if (viewMoved) {
    passes_->geometry.run(cameraMesh(), model, camera);
    geometryValid_ = true;
    times_.geometryRan = true;
  }
  const ScreenRect rect =
      projectedBounds(mesh_->boundsMin(), mesh_->boundsMax(), camera.viewProj * model, width, height);
  const bool marble = scene.render.mode == RenderMode::Marble;
  // `marble` sees the vein models through the polish: their albedo depends on the scattering too.
  const float seen = marble ? seenVeinAttenuation(scene) : 0.0f;
  if (viewMoved || !sameGroups(scene.material, lastMaterial_, kAlbedoGroups) || seen != lastSeenAttenuation_ ||
      (seen > 0.0f && scene.material.ior != lastMaterial_.ior) || albedoFromPost_ != marble)
    albedoValid_ = false;
  lastSeenAttenuation_ = seen;
  passes_->albedo.resize(width, height, passes_->geometry.depthTexture());
  // `marble` evaluates the pattern in its post pass (DiffuseSource::Pattern); the other modes
  // read the albedo in the lighting pass.
  if (!albedoValid_ && !marble && modeShowsAlbedo(scene.render.mode)) {
    passes_->albedo.run(passes_->geometry.depthTexture(), passes_->geometry.normalTexture(), model, camera,
                        scene.material, turbulence_.update(scene.material), rect);
    albedoValid_ = true;
    albedoFromPost_ = false;
    times_.albedoRan = true;
  }
  lastLight_ = light;
  lastCamera_ = camera;
  lastModel_ = model;
  lastMaterial_ = scene.material;
  const float lightTexelWorld = 2.0f * kBoundingRadius / static_cast<float>(passes_->lightDepth.size());
  // Lighting and blur depend on neither the exposure nor the background (post-only), nor --
  // for `marble` -- on the albedo (a pattern change re-runs only the post pass, which evaluates
  // it). The other modes read the albedo in the lighting pass.
  const bool lightingCurrent = lightingValid_ && !times_.lightDepthRan && !viewMoved &&
                               sameLightingInputs(scene, lastLightingScene_) && (marble || !times_.albedoRan);
  if (!lightingCurrent) {
    const int scale = subsurfaceScale(scene.render);
    if (marble) {
      const bool remade = passes_->blurDepth.resize(width, height, scale, passes_->geometry.depthTexture());
      if (remade || viewMoved || !blurDepthValid_) {
        passes_->blurDepth.run(rect);
        blurDepthValid_ = true;
        times_.blurDepthRan = scale != 1;
      }
    }
    const LightingInputs in{passes_->albedo.albedoTexture(), passes_->geometry.normalTexture(),
                            passes_->geometry.depthTexture(), passes_->lightDepth.distanceTexture(),
                            passes_->lightDepth.depthTexture()};
    passes_->lighting.resize(width, height, scale, passes_->geometry.depthTexture(), passes_->blurDepth.depthTexture());
    passes_->lighting.run(in, camera, light, scene.light, scene.material, scene, lightTexelWorld, rect, environment());
    if (marble) {
      passes_->blur.resize(width, height, scale, passes_->blurDepth.depthTexture());
      passes_->blur.run({passes_->lighting.enteringTexture()}, camera, scene, height,
                        rect);
    }
    times_.lightingRan = true;
    lightingValid_ = true;
    lastLightingScene_ = scene;
  }
  lastWidth_ = width;
  lastHeight_ = height;
  lastScene_ = scene;
  lastRect_ = rect;
  lastLightTexelWorld_ = lightTexelWorld;

  // The post pass writes the display image (resized with the frame); FXAA or a copy takes it
  // to the target. For `marble` it also writes what later frames can reuse: the diffuse part,
  // and the albedo when it evaluated the pattern.
  const bool fxaa = scene.render.antialias == Antialias::Fxaa;
  passes_->post.resize(width, height);
  OffscreenTarget& display = surfaceTarget(displayImage_, width, height, GL_RGBA8);
  display.attach(GL_COLOR_ATTACHMENT1, passes_->post.diffuseTexture());
  display.attach(GL_COLOR_ATTACHMENT2, passes_->albedo.albedoTexture());
  const DiffuseSource source = !albedoValid_                            ? DiffuseSource::Pattern
                               : times_.lightingRan || !diffuseValid_ ? DiffuseSource::StoredAlbedo
                                                                      : DiffuseSource::Stored;
  const GLuint turbulenceGrid = marble && source == DiffuseSource::Pattern ? turbulence_.update(scene.material) : 0;
  passes_->post.run(postInputs(), scene, {camera, light, lightTexelWorld, environment(), model, turbulenceGrid},
                    display.fbo(), width, height, rect,
                    fxaa ? PostPass::Output::DisplayWithLuma : PostPass::Output::Display, source);
  times_.diffuseSource = marble ? static_cast<int>(source) : -1;
  times_.postRan = true;
  times_.fxaaRan = fxaa;
  if (marble) {  // the post pass wrote it (other modes: the albedo pass, or not needed)
    albedoValid_ = true;
    albedoFromPost_ = true;
  }
  diffuseValid_ = marble;  // other modes do not write it
  const bool stage = sceneHasStage(scene);
  if (stage) {
    if (scene.render.ground) passes_->stage.updateBottomMap(*mesh_, model);
    passes_->stage.run(scene, camera, light, lightTexelWorld, environment(), passes_->geometry.depthTexture(),
                       passes_->lightDepth.depthTexture(), mesh_->boundsMin().y - 0.002f, display.fbo(), width, height,
                       fxaa);
    times_.stageRan = true;
  }
  if (!fxaa) {
    glBlitNamedFramebuffer(display.fbo(), targetFbo, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
  } else {
    // FXAA changes nothing on flat background: it draws only the tiles the mesh can cover (and
    // their neighbours); the rest of the target is the background.
    // The light's map, or a stage around the object: content everywhere.
    const bool wholeFrame = scene.render.mode == RenderMode::LightDepth || stage;
    passes_->fxaa.run(display.texture(), targetFbo, width, height, aaSpans(camera.viewProj * model, width, height, wholeFrame),
                      glm::clamp(scene.render.background, 0.0f, 1.0f));
  }
}

const std::vector<ScreenRect>& Renderer::aaSpans(const glm::mat4& mvp, int width, int height, bool wholeFrame) {
  if (width != aaSpansWidth_ || height != aaSpansHeight_ || wholeFrame != aaSpansWholeFrame_ ||
      !sameMatrix(mvp, aaSpansMvp_)) {
    // Margin 2: FXAA changes a pixel only if one of its neighbours differs (one pixel), plus rounding.
    aaSpans_ = wholeFrame ? std::vector<ScreenRect>{{0, 0, width, height}} : coveredSpans(meshCells_, mvp, width, height, 2);
    aaSpansMvp_ = mvp;
    aaSpansWidth_ = width;
    aaSpansHeight_ = height;
    aaSpansWholeFrame_ = wholeFrame;
  }
  return aaSpans_;
}

OffscreenTarget& Renderer::surfaceTarget(std::optional<OffscreenTarget>& target, int width, int height,
                                         GLenum format) {
  if (!target || target->width() != width || target->height() != height) target.emplace(width, height, format);
  target->attach(GL_DEPTH_ATTACHMENT, passes_->geometry.depthTexture());
  return *target;
}

PostInputs Renderer::postInputs() const {
  return {passes_->lighting.hdrTexture(),      passes_->geometry.depthTexture(), passes_->blur.resultTexture(),
          passes_->albedo.albedoTexture(), passes_->geometry.normalTexture(),
          passes_->lightDepth.depthTexture()};
}

PassTimes Renderer::passTimes(bool wait) {
  auto get = [wait](PassTimer& t) { return wait ? t.waitMilliseconds() : t.milliseconds(); };
  times_.lightDepthMs = get(passes_->lightDepth.timer());
  times_.geometryMs = get(passes_->geometry.timer());
  times_.albedoMs = get(passes_->albedo.timer());
  times_.lightingMs = get(passes_->lighting.timer());
  times_.subsurfaceBlurMs = get(passes_->blur.timer());
  times_.postMs = get(passes_->post.timer());
  times_.floorMs = get(passes_->floor.timer());
  times_.fxaaMs = get(passes_->fxaa.timer());
  times_.blurDepthMs = get(passes_->blurDepth.timer());
  times_.stageMs = get(passes_->stage.timer());
  return times_;
}

size_t Renderer::glBytes() const {
  return passes_->lightDepth.bytes() + passes_->geometry.bytes() + passes_->albedo.bytes() +
         passes_->lighting.bytes() + passes_->blur.bytes() + passes_->blurDepth.bytes() + passes_->post.bytes() + passes_->stage.bytes() + (displayImage_ ? displayImage_->bytes() : 0) +
         (mesh_ ? mesh_->bytes() : 0) + (lightMesh_ ? lightMesh_->bytes() : 0) +
         (interactionMesh_ ? interactionMesh_->bytes() : 0) + (environment_ ? environment_->bytes() : 0) + turbulence_.bytes();
}

ImageRGBF Renderer::readHdr() {
  const int w = lastWidth_, h = lastHeight_;
  ImageRGBF img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
  if (!geometryValid_ || w <= 0 || h <= 0) return img;
  // The last frame once more, through the same post pass, into a float target, linear.
  OffscreenTarget& readback = surfaceTarget(hdrReadback_, w, h, GL_RGBA32F);
  // The diffuse part the frame stored (`marble`); nothing else is written.
  passes_->post.run(postInputs(), lastScene_, {lastCamera_, lastLight_, lastLightTexelWorld_, environment(), lastModel_},
                    readback.fbo(), w, h, lastRect_, PostPass::Output::Linear, DiffuseSource::Stored);
  // RGB: linear light; A: coverage (the post pass writes 1 on the object, 0 elsewhere).
  std::vector<float> rgba(static_cast<size_t>(w) * h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, readback.fbo());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  img.alpha.resize(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t from = (static_cast<size_t>(h - 1 - y) * w + x) * 4, to = static_cast<size_t>(y) * w + x;
      std::copy_n(rgba.begin() + static_cast<ptrdiff_t>(from), 3, img.pixels.begin() + static_cast<ptrdiff_t>(to * 3));
      img.alpha[to] = rgba[from + 3];
    }
  return img;
}

}  // namespace marble
