#include "marble/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <numeric>

#include "marble/gl/checked_calls.h"
#include "marble/mesh/mesh_optimize.h"
#include "marble/render/mesh_detail.h"
#include "marble/scene/material_params.h"

namespace marble {

struct Renderer::Passes {
  explicit Passes(const ShaderLibrary& s)
      : lightDepth(s), geometry(s), albedo(s), blurDepth(s), bounce(s), lighting(s), blur(s), post(s), floor(s), fxaa(s), stage(s) {}
  LightDepthPass lightDepth;
  GeometryPass geometry;
  AlbedoPass albedo;
  BlurDepthPass blurDepth;
  BouncePass bounce;
  LightingPass lighting;
  SubsurfaceBlurPass blur;
  PostPass post;
  FloorPass floor;
  FxaaPass fxaa;
  StagePass stage;
};

void Renderer::invalidateStage() { passes_->stage.invalidateBottomMap(); }

void Renderer::invalidate() {
  cache_.forget();
  storedDiffuse_.reset();
  lastOutput_.reset();
  invalidateStage();
}

void Renderer::interactionCopyRemade() {
  if (detail_ == MeshDetail::Interaction) cache_.changed(PassInput::CameraMesh);
}

void Renderer::setTurbulenceGridEnabled(bool enabled) {
  turbulence_.setEnabled(enabled);
  cache_.changed(PassInput::TurbulenceGrid);
}

namespace {
ScreenRect boundingUnion(const ScreenRect& a, const ScreenRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
  return {x0, y0, x1 - x0, y1 - y0};
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
  forgetFurtherBounces();  // made again at the next `marble` frame
  meshCells_ = OccupancyGrid(cpuMesh_);
  aaSpansWidth_ = 0;  // made anew for this mesh
  interactionMesh_.reset();
  interactionIsFull_ = false;
  interactionIsLightProxy_ = false;
  makeLightProxy();
  cache_.changed(PassInput::LightMesh);
  cache_.changed(PassInput::CameraMesh);
  invalidateStage();  // the ground's contact map is the stage's own (StagePass)
}

void Renderer::makeLightProxy() {
  lightMesh_.reset();
  reducedLightMesh_.reset();
  lightProxyMesh_ = Mesh();
  lightProxyErrorUnits_ = 0.0f;
  lightProxyJob_.reset();  // a copy still being made for an earlier mesh is abandoned
  const size_t triangles = cpuMesh_.triangleCount();
  if (!lightProxyEnabled_ || triangles <= kLightProxyMinTriangles) return;
  const auto target = std::min(kLightProxyMaxTriangles,
                               static_cast<size_t>(static_cast<double>(triangles) * kLightProxyTriangleFraction));
  const float maxError = lightProxyMaxErrorUnits(passes_->lightDepth.fullSize());
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
  reducedLightMesh_.reset();
  lightProxyMesh_ = std::move(proxy.mesh);
}

void Renderer::adoptLightProxy(bool wait) {
  if (!lightProxyJob_ || (!wait && !lightProxyJob_->ready())) return;
  SimplifiedMesh proxy = lightProxyJob_->take();
  lightProxyJob_.reset();
  useLightProxy(std::move(proxy));
  forgetFurtherBounces();  // made from the proxy from now on, as a fresh renderer's
  interactionMesh_.reset();  // made from the proxy from now on
  interactionIsFull_ = false;
  interactionIsLightProxy_ = false;
  // Every pass, as after setMesh, not only those that read the light's mesh: the next frame is
  // then a fresh renderer's bit for bit (a `marble` frame reusing the stored albedo can differ
  // from one evaluating the pattern by one level in a pixel: two programs need not round alike).
  invalidate();
}

void Renderer::forgetFurtherBounces() {
  further_.reset();
  furtherJob_.reset();  // a job still running for an earlier mesh is abandoned
  furtherStale_ = true;
  passes_->bounce.clearFurtherGrid();  // none until they are made again
}

void Renderer::makeFurtherBounces() {
  if (further_) return;
  // From the light's proxy where there is one (its error is a fraction of the light map's texel): a
  // 1.6 M-triangle scan's proxy simplifies to the patches in about a second, its full mesh in 11.7 s
  // (two shared cores). So while the proxy is still being made (the viewer), nothing: the frames
  // until then have no further bounces.
  if (lightProxyJob_) return;
  const Mesh& source = lightProxyMesh_.positions.empty() ? cpuMesh_ : lightProxyMesh_;
  if (!lightProxyInBackground_ || furtherInForeground_) {
    further_ = furtherJob_ ? furtherJob_->take() : std::make_unique<FurtherRadiosity>(source);
    furtherJob_.reset();
    furtherInForeground_ = false;
    return;
  }
  // The viewer: on a worker thread (0.3-1 s), the frames until then without further bounces;
  // adoptFurtherBounces takes them and the next frame re-runs every pass.
  if (!furtherJob_)
    furtherJob_.emplace([mesh = std::make_shared<const Mesh>(source)] { return std::make_unique<FurtherRadiosity>(*mesh); });
}

void Renderer::adoptFurtherBounces() {
  if (!furtherJob_ || !furtherJob_->ready()) return;
  further_ = furtherJob_->take();
  furtherJob_.reset();
  furtherStale_ = true;
  // Every pass, as adoptLightProxy: the next frame is then a fresh renderer's bit for bit.
  invalidate();
}

void Renderer::waitForBackgroundWork() {
  adoptLightProxy(true);
  if (furtherJob_) {
    further_ = furtherJob_->take();
    furtherJob_.reset();
    furtherStale_ = true;
    invalidate();
  } else if (!further_) {
    furtherInForeground_ = true;  // the next `marble` frame makes them before it draws
  }
}

void Renderer::setLightProxyEnabled(bool enabled) {
  if (enabled == lightProxyEnabled_) return;
  lightProxyEnabled_ = enabled;
  if (mesh_) makeLightProxy();
  forgetFurtherBounces();  // made from the proxy (or the mesh) again at the next `marble` frame
  interactionMesh_.reset();  // it is made from the proxy: made again at its next use
  interactionIsFull_ = false;
  interactionIsLightProxy_ = false;
  cache_.changed(PassInput::LightMesh);
  interactionCopyRemade();
}

const GpuMesh& Renderer::lightMeshFor(int mapSize) {
  if (mapSize >= passes_->lightDepth.fullSize() || !lightMesh_) return lightMesh();
  if (!reducedLightMesh_ || reducedLightMeshSize_ != mapSize) {
    // As many triangles as the map has fewer texels at most; the error bound binds first on the
    // dragon (docs/performance.md, "Twenty-third session").
    const double texelShare = std::pow(static_cast<double>(mapSize) / passes_->lightDepth.fullSize(), 2.0);
    const auto target = std::max<size_t>(1, static_cast<size_t>(static_cast<double>(lightProxyMesh_.triangleCount()) * texelShare));
    reducedLightMesh_.emplace(simplifiedMesh(lightProxyMesh_, target, lightProxyMaxErrorUnits(mapSize)).mesh);
    reducedLightMeshSize_ = mapSize;
  }
  return *reducedLightMesh_;
}

size_t Renderer::lightMapTriangleCount() {
  if (!mesh_) return 0;
  return lightMeshFor(lightMapSize()).triangleCount();
}

size_t Renderer::lightTriangleCount() const {
  if (!mesh_) return 0;
  return lightMesh().triangleCount();
}

const GpuMesh& Renderer::cameraMesh() {
  if (detail_ == MeshDetail::Full || !mesh_) return *mesh_;
  if (!interactionMesh_ && !interactionIsFull_ && !interactionIsLightProxy_) {
    if (lightMesh_ && lightProxyMesh_.triangleCount() <= kInteractionTriangles) {
      // The light's proxy is the copy (no second one): the dragon's 100,000 triangles draw 29,652
      // while the view moves, within the proxy's half a light texel (≈ 0.7 pixel at 800²).
      interactionIsLightProxy_ = true;
    } else if (cpuMesh_.triangleCount() <= kInteractionTriangles) {
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
  if (interactionIsLightProxy_) return *lightMesh_;
  return interactionMesh_ ? *interactionMesh_ : *mesh_;
}

void Renderer::setMeshDetail(MeshDetail detail) {
  if (detail == detail_) return;
  detail_ = detail;
  // The camera's passes re-run with the other mesh (the interaction copy may be the full mesh
  // itself: re-running then costs one frame and changes nothing).
  cache_.changed(PassInput::CameraMesh);
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
  cache_.changed(PassInput::EnvironmentMap);
}

void Renderer::clearEnvironmentMap() {
  environment_.reset();
  cache_.changed(PassInput::EnvironmentMap);
}

void Renderer::reloadShaders() {
  auto fresh = std::make_unique<Passes>(shaders_);  // throws on error; old passes stay
  // Every specialized program now, not at its first use: an error must show here, while
  // the previous programs are still in use.
  fresh->albedo.compileAll();
  fresh->lighting.compileAll();
  fresh->post.compileAll();
  fresh->blur.compileAll();
  passes_ = std::move(fresh);
  passes_->lightDepth.setMapSize(lightMapSize());
  invalidate();  // new passes: nothing they stored survives
}

void Renderer::setResolutionScale(float scale) {
  resolutionScale_ = std::clamp(scale, kMinResolutionScale, 1.0f);
  updateLightMapSize();
}

void Renderer::setLightMapDetail(LightMapDetail detail) {
  lightMapDetail_ = detail;
  updateLightMapSize();
}

int Renderer::lightMapSize() const {
  const int full = passes_->lightDepth.fullSize();
  if (lightMapDetail_ == LightMapDetail::Full) return full;
  return std::max(1, static_cast<int>(std::lround(static_cast<float>(full) * resolutionScale_)));
}

void Renderer::updateLightMapSize() {
  const int size = lightMapSize();
  if (size == passes_->lightDepth.size()) return;
  passes_->lightDepth.setMapSize(size);
  cache_.changed(PassInput::LightMesh);  // the light's pass draws other maps: it and its readers re-run
}

Renderer::FrameToken Renderer::render(const Scene& scene, const glm::mat4& model, GLuint targetFbo, int width,
                                      int height) {
  const gl::NoProgramCurrentOnExit noProgramAfter;
  adoptLightProxy(false);
  adoptFurtherBounces();
  if (!mesh_ || width <= 0 || height <= 0) return {};
  const int reducedWidth = std::max(1, static_cast<int>(std::lround(static_cast<float>(width) * resolutionScale_)));
  const int reducedHeight = std::max(1, static_cast<int>(std::lround(static_cast<float>(height) * resolutionScale_)));
  if (reducedWidth == width && reducedHeight == height) {
    const FrameToken frame = drawFrame(scene, model, targetFbo, width, height);
    lastOutput_->resolutionScale = resolutionScale_;
    return frame;
  }
  if (!reducedFrame_ || reducedFrame_->width() != reducedWidth || reducedFrame_->height() != reducedHeight)
    reducedFrame_.emplace(reducedWidth, reducedHeight);
  const FrameToken frame = drawFrame(scene, model, reducedFrame_->fbo(), reducedWidth, reducedHeight);
  stretchReducedFrame(scene, targetFbo, width, height);
  // What the caller's target holds: this scene at the caller's size, drawn at this scale.
  lastOutput_ = OutputKey{scene, model, frame, width, height, cache_.stateRevision(), resolutionScale_};
  return frame;
}

void Renderer::stretchReducedFrame(const Scene& scene, GLuint targetFbo, int width, int height) {
  const int rw = reducedFrame_->width(), rh = reducedFrame_->height();
  // The stretch maps blocks of srcX × srcY reduced pixels onto blocks of dstX × dstY target
  // pixels exactly (integer corners: a part of the frame is sampled where the whole frame's
  // stretch samples it).
  const int gx = std::gcd(width, rw), gy = std::gcd(height, rh);
  const int srcX = rw / gx, srcY = rh / gy, dstX = width / gx, dstY = height / gy;
  if (!contentRect_) {
    gl::blitFramebuffer(reducedFrame_->fbo(), targetFbo, 0, 0, rw, rh, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                        GL_LINEAR);
    return;
  }
  // Outside contentRect_ the reduced frame is the flat background (as FXAA and the post pass
  // clear it), which a bilinear stretch leaves as it is: clear the target to it and stretch
  // only the rest -- grown by 2 reduced pixels (the filter's reach), out to whole blocks. On
  // llvmpipe the stretch of a whole 1080p frame cost ≈ 15-30 ms at load 10 (performance.md).
  const ScreenRect& c = *contentRect_;
  const int x0 = std::max(0, c.x - 2) / srcX, x1 = std::min(gx, (c.x + c.width + 2 + srcX - 1) / srcX);
  const int y0 = std::max(0, c.y - 2) / srcY, y1 = std::min(gy, (c.y + c.height + 2 + srcY - 1) / srcY);
  const glm::vec4 background(glm::clamp(scene.render.background, 0.0f, 1.0f), 1.0f);
  gl::clearFramebuffer(targetFbo, GL_COLOR, 0, &background.x);
  if (x1 <= x0 || y1 <= y0) return;
  gl::blitFramebuffer(reducedFrame_->fbo(), targetFbo, x0 * srcX, y0 * srcY, x1 * srcX, y1 * srcY, x0 * dstX,
                      y0 * dstY, x1 * dstX, y1 * dstY, GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

Renderer::FrameToken Renderer::drawFrame(const Scene& scene, const glm::mat4& model, GLuint targetFbo, int width,
                                         int height) {
  const CameraMatrices camera = cameraMatrices(scene.camera, static_cast<float>(width) / static_cast<float>(height));
  times_.ran = {};
  times_.diffuseSource = -1;
  times_.surfaceReuse = -1;
  // One counter for every renderer in the process: a token is never handed out twice, so one
  // renderer's token never matches another's frame either. 64 bits do not wrap.
  static std::atomic<uint64_t> lastSerial{0};
  const FrameToken frame(++lastSerial);
  lastOutput_ = OutputKey{scene, model, frame, width, height, cache_.stateRevision(), 1.0f};
  if (scene.render.mode == RenderMode::Floor) {
    passes_->floor.run(cameraMesh(), model, camera, scene.light.position, scene.material.base_color, scene.render.background,
                       targetFbo, width, height);
    times_.ran[Pass::Floor] = true;
    contentRect_.reset();  // the floor pass draws the whole frame
    return frame;
  }
  const bool marble = scene.render.mode == RenderMode::Marble;
  // `marble` sees the vein models through the polish: their albedo depends on the scattering too.
  const FrameInputs now{scene, model, camera, lightMatrices(scene.light), width, height,
                        marble ? seenVeinAttenuation(scene) : 0.0f};
  // Whether a cached pass must run; and that it ran.
  auto stale = [&](Pass p) { return !cache_.current(p, now); };
  auto ran = [&](Pass p) {
    cache_.made(p, now);
    times_.ran[p] = true;
  };
  const LightMatrices& light = now.light;
  if (stale(Pass::LightDepth)) {
    passes_->lightDepth.run(lightMeshFor(passes_->lightDepth.size()), model, light);
    passes_->bounce.markEntriesStale();
    furtherStale_ = true;  // the light, the model or the mesh moved: the radiosity is solved again
    ran(Pass::LightDepth);
  }
  passes_->geometry.resize(width, height);
  if (stale(Pass::Geometry)) {
    passes_->geometry.run(cameraMesh(), model, camera, marble);
    ran(Pass::Geometry);
  }
  const ScreenRect rect =
      projectedBounds(mesh_->boundsMin(), mesh_->boundsMax(), camera.viewProj * model, width, height);
  // The albedo texture: written by the albedo pass, or -- `marble` -- by the post pass
  // evaluating the pattern (DiffuseSource::Pattern); its inputs are the albedo pass's either way.
  passes_->albedo.resize(width, height, passes_->geometry.depthTexture());
  bool albedoCurrent = !stale(Pass::Albedo);
  if (!albedoCurrent && passInFrame(Pass::Albedo, scene)) {
    passes_->albedo.run(passes_->geometry.depthTexture(), passes_->geometry.normalTexture(), model, camera,
                        scene.material, turbulence_.update(scene.material), rect);
    ran(Pass::Albedo);
    albedoCurrent = true;
  }
  const float lightTexelWorld = 2.0f * kBoundingRadius / static_cast<float>(passes_->lightDepth.size());
  const int scale = subsurfaceScale(scene.render);
  if (marble) {
    // At full resolution the G-buffer's depth serves (resize points the pass at it).
    const bool remade = passes_->blurDepth.resize(width, height, scale, passes_->geometry.depthTexture());
    if (passInFrame(Pass::BlurDepth, scene) && (remade || stale(Pass::BlurDepth))) {
      passes_->blurDepth.run(rect);
      ran(Pass::BlurDepth);
    }
  }
  if (marble) {
    passes_->bounce.resize(width, height, scale);
    if (stale(Pass::Bounce)) {
      // The further bounces: the form factors once per mesh, the solve once per light (its cost
      // falls in the bounce pass's share of the frame: docs/performance.md).
      makeFurtherBounces();
      if (further_ && furtherStale_) {
        passes_->bounce.setFurtherGrid(further_->solve(scene.light, model), model);
        furtherStale_ = false;
      }
      passes_->bounce.run({passes_->geometry.normalTexture(), passes_->geometry.depthTexture(),
                           passes_->lightDepth.bouncePositionTexture(), passes_->lightDepth.bounceNormalTexture(),
                           passes_->lightDepth.bounceSize(), passes_->lightDepth.layersTexture(),
                           passes_->lightDepth.layersSize()},
                          camera, light, scene.light, scene.material, lightTexelWorld, rect,
                          !cache_.currentButMaterial(Pass::Bounce, now));
      ran(Pass::Bounce);
    }
  }
  if (stale(Pass::Lighting)) {
    const LightingInputs in{passes_->albedo.albedoTexture(),
                            passes_->geometry.normalTexture(),
                            passes_->geometry.depthTexture(),
                            passes_->lightDepth.distanceTexture(),
                            passes_->lightDepth.depthTexture(),
                            passes_->bounce.bounceTexture(),
                            passes_->bounce.gridLayout(),
                            passes_->bounce.entryTexture(),
                            passes_->lightDepth.layersTexture()};
    // The blur's depth only in `marble`: other modes do not resize it, so at scale 1 it may still
    // name the G-buffer depth of an earlier frame size, deleted since (0 detaches).
    passes_->lighting.resize(width, height, scale, passes_->geometry.depthTexture(),
                             marble ? passes_->blurDepth.depthTexture() : 0);
    passes_->lighting.run(in, camera, light, scene.light, scene.material, scene, lightTexelWorld, rect, environment());
    ran(Pass::Lighting);
  }
  if (marble && stale(Pass::SubsurfaceBlur)) {
    passes_->blur.resize(width, height, scale, passes_->blurDepth.depthTexture());
    passes_->blur.run({passes_->lighting.enteringTexture()}, camera, scene, height, rect);
    ran(Pass::SubsurfaceBlur);
  }
  lastFrame_ = now;
  lastRect_ = rect;

  // The post pass writes the display image (resized with the frame); FXAA or a copy takes it
  // to the target. For `marble` it also writes what later frames can reuse: the diffuse part,
  // and the albedo when it evaluated the pattern.
  const bool fxaa = scene.render.antialias == Antialias::Fxaa;
  passes_->post.resize(width, height);
  OffscreenTarget& display = surfaceTarget(displayImage_, width, height, GL_RGBA8);
  display.attach(GL_COLOR_ATTACHMENT1, passes_->post.diffuseTexture());
  display.attach(GL_COLOR_ATTACHMENT2, passes_->albedo.albedoTexture());
  auto sameReads = [this](const PerPass<uint64_t>& made) {
    for (const PassDecl& q : passList())
      if ((kStoredDiffuseReads & passBit(q.pass)) != 0 && made[q.pass] != cache_.generations()[q.pass]) return false;
    return true;
  };
  const DiffuseSource source = !albedoCurrent                               ? DiffuseSource::Pattern
                               : !storedDiffuse_ || !sameReads(*storedDiffuse_) ? DiffuseSource::StoredAlbedo
                                                                               : DiffuseSource::Stored;
  const GLuint turbulenceGrid = marble && source == DiffuseSource::Pattern ? turbulence_.update(scene.material) : 0;
  // A frame that changed only the pattern: the reflected and the upsampled blurred light are the
  // last frame's. The first such frame stores them, the next ones read them (SurfaceReuse); a
  // frame that changed anything else (the camera, the light) stores nothing, so costs no more.
  SurfaceReuse reuse = SurfaceReuse::None;
  const SurfaceKey surface{now, cache_.generations(), cache_.stateRevision()};
  if (marble && source == DiffuseSource::Pattern) {
    if (storedSurface_ && storedSurface_->same(surface))
      reuse = SurfaceReuse::Read;
    else if (lastSurface_ && lastSurface_->same(surface))
      reuse = SurfaceReuse::Store;
  }
  const bool store = reuse == SurfaceReuse::Store;
  display.attach(GL_COLOR_ATTACHMENT3, store ? passes_->post.surfaceLightTexture() : 0);
  display.attach(GL_COLOR_ATTACHMENT4, store ? passes_->post.surfaceReflectedTexture() : 0);
  passes_->post.run(postInputs(), scene, {camera, light, lightTexelWorld, environment(), model, turbulenceGrid},
                    display.fbo(), width, height, rect,
                    fxaa ? PostPass::Output::DisplayWithLuma : PostPass::Output::Display, source, reuse);
  times_.ran[Pass::Post] = true;
  if (marble) {
    lastSurface_ = surface;
    if (store) storedSurface_ = surface;
    if (source == DiffuseSource::Pattern) times_.surfaceReuse = static_cast<int>(reuse);
    times_.diffuseSource = static_cast<int>(source);
    if (source == DiffuseSource::Pattern) cache_.made(Pass::Albedo, now);  // the post pass wrote it
    if (source != DiffuseSource::Stored) storedDiffuse_ = cache_.generations();
  } else {
    storedDiffuse_.reset();  // only `marble`'s post pass writes it
  }
  if (passInFrame(Pass::Stage, scene)) {
    if (scene.render.ground) passes_->stage.updateBottomMap(*mesh_, model);
    passes_->stage.run(scene, camera, light, lightTexelWorld, environment(), passes_->geometry.depthTexture(),
                       passes_->lightDepth.depthTexture(), mesh_->boundsMin().y - 0.002f, display.fbo(), width, height,
                       fxaa);
    times_.ran[Pass::Stage] = true;
  }
  // The light's map, or a stage around the object: content everywhere.
  const bool wholeFrame = scene.render.mode == RenderMode::LightDepth || times_.ran[Pass::Stage];
  contentRect_.reset();
  if (!wholeFrame) contentRect_ = rect;
  if (!fxaa) {
    gl::blitFramebuffer(display.fbo(), targetFbo, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                        GL_NEAREST);
  } else {
    // FXAA changes nothing on flat background: it draws only the tiles the mesh can cover (and
    // their neighbours); the rest of the target is the background.
    const std::vector<ScreenRect>& spans = aaSpans(camera.viewProj * model, width, height, wholeFrame);
    passes_->fxaa.run(display.texture(), targetFbo, width, height, spans, glm::clamp(scene.render.background, 0.0f, 1.0f));
    if (contentRect_)  // FXAA writes its spans (the mesh's tiles, grown): they hold content too
      for (const ScreenRect& r : spans) contentRect_ = boundingUnion(*contentRect_, r);
    times_.ran[Pass::Fxaa] = true;
  }
  return frame;
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

bool Renderer::SurfaceKey::same(const SurfaceKey& o) const {
  if (stateRevision != o.stateRevision || !sameButPattern(inputs, o.inputs)) return false;
  for (const PassDecl& q : passList())
    if (q.pass != Pass::Albedo && generations[q.pass] != o.generations[q.pass]) return false;
  return true;
}

OffscreenTarget& Renderer::surfaceTarget(std::optional<OffscreenTarget>& target, int width, int height,
                                         GLenum format) {
  if (!target || target->width() != width || target->height() != height) target.emplace(width, height, format);
  target->attach(GL_DEPTH_ATTACHMENT, passes_->geometry.depthTexture());
  return *target;
}

PostInputs Renderer::postInputs() const {
  return {passes_->lighting.hdrTexture(),      passes_->geometry.depthTexture(), passes_->blur.resultTexture(),
          passes_->albedo.albedoTexture(), passes_->geometry.specularNormalTexture(),
          passes_->lightDepth.depthTexture(), passes_->lighting.mirrorHitTexture()};
}

PassTimer& Renderer::timerOf(Pass p) {
  switch (p) {
    case Pass::LightDepth: return passes_->lightDepth.timer();
    case Pass::Geometry: return passes_->geometry.timer();
    case Pass::Albedo: return passes_->albedo.timer();
    case Pass::BlurDepth: return passes_->blurDepth.timer();
    case Pass::Bounce: return passes_->bounce.timer();
    case Pass::Lighting: return passes_->lighting.timer();
    case Pass::SubsurfaceBlur: return passes_->blur.timer();
    case Pass::Post: return passes_->post.timer();
    case Pass::Stage: return passes_->stage.timer();
    case Pass::Fxaa: return passes_->fxaa.timer();
    case Pass::Floor: return passes_->floor.timer();
  }
  return passes_->post.timer();  // not reached: every Pass is listed
}

PassTimes Renderer::passTimes(bool wait) {
  for (const PassDecl& d : passList()) {
    PassTimer& t = timerOf(d.pass);
    times_.ms[d.pass] = wait ? t.waitMilliseconds() : t.milliseconds();
  }
  return times_;
}

int Renderer::bounceRefinedTexels() const { return passes_->bounce.refinedTexelCount(); }
void Renderer::setBounceSkipsBackground(bool on) {
  passes_->bounce.setSkipsBackground(on);
  invalidate();
}
void Renderer::setGeometryCullsHiddenFaces(bool on) {
  passes_->geometry.setCullsHiddenFaces(on);
  invalidate();
}

void Renderer::setGeometryCullsOnCpu(bool on) {
  passes_->geometry.setCullsOnCpu(on);
  invalidate();
}
void Renderer::setLightCullsHiddenFaces(bool on) {
  passes_->lightDepth.setCullsHiddenFaces(on);
  invalidate();
}

size_t Renderer::glBytes() const {
  return passes_->lightDepth.bytes() + passes_->geometry.bytes() + passes_->albedo.bytes() +
         passes_->lighting.bytes() + passes_->blur.bytes() + passes_->blurDepth.bytes() + passes_->bounce.bytes() + passes_->post.bytes() + passes_->stage.bytes() + (displayImage_ ? displayImage_->bytes() : 0) +
         (mesh_ ? mesh_->bytes() : 0) + (lightMesh_ ? lightMesh_->bytes() : 0) + (reducedLightMesh_ ? reducedLightMesh_->bytes() : 0) +
         (interactionMesh_ ? interactionMesh_->bytes() : 0) + (environment_ ? environment_->bytes() : 0) + turbulence_.bytes() +
         (reducedFrame_ ? reducedFrame_->bytes() : 0);
}

ImageRGBF Renderer::readHdr() {
  const gl::NoProgramCurrentOnExit noProgramAfter;
  const int w = lastFrame_ ? lastFrame_->width : 0, h = lastFrame_ ? lastFrame_->height : 0;
  ImageRGBF img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
  // Nothing to read when the G-buffer no longer holds the last frame's view (a new mesh, shaders).
  // Nor when the light's maps were redrawn or swapped since (a new mesh, setLightMapDetail).
  if (!lastFrame_ || !cache_.current(Pass::Geometry, *lastFrame_) || !cache_.current(Pass::LightDepth, *lastFrame_) ||
      w <= 0 || h <= 0)
    return img;
  const FrameInputs& last = *lastFrame_;
  const float lightTexelWorld = 2.0f * kBoundingRadius / static_cast<float>(passes_->lightDepth.size());
  // The last frame once more, through the same post pass, into a float target, linear.
  OffscreenTarget& readback = surfaceTarget(hdrReadback_, w, h, GL_RGBA32F);
  // The diffuse part the frame stored (`marble`); nothing else is written.
  passes_->post.run(postInputs(), last.scene, {last.camera, last.light, lightTexelWorld, environment(), last.model},
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
