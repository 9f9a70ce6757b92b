#pragma once
// The renderer owns the passes and runs them in the order of passList() (render/pass_list.h,
// which also says what each reads; docs/architecture.md "One frame" draws it): a cached pass
// only when an input it declares changed since its output was made (render/pass_cache.h), the
// passes that draw the picture in every frame that is drawn. The screen passes draw only inside
// the mesh's screen rectangle. The viewer and the CLI own nothing of GL but a context and a Renderer.
#include <memory>
#include <optional>

#include "marble/gl/shader_library.h"
#include "marble/mesh/background_simplify.h"
#include "marble/render/albedo_pass.h"
#include "marble/render/blur_depth_pass.h"
#include "marble/render/bounce_pass.h"
#include "marble/render/environment_map.h"
#include "marble/render/floor_pass.h"
#include "marble/core/background_job.h"
#include "marble/render/further_radiosity.h"
#include "marble/render/fxaa_pass.h"
#include "marble/render/geometry_pass.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/light_depth_pass.h"
#include "marble/render/lighting_pass.h"
#include "marble/render/offscreen_target.h"
#include "marble/render/pass_cache.h"
#include "marble/render/pass_list.h"
#include "marble/render/post_pass.h"
#include "marble/render/screen_tiles.h"
#include "marble/render/stage_pass.h"
#include "marble/render/subsurface_blur_pass.h"
#include "marble/render/turbulence_texture.h"
#include "marble/core/image.h"
#include "marble/scene/scene.h"

namespace marble {

class Renderer {
public:
  explicit Renderer(ShaderLibrary shaders = ShaderLibrary());
  ~Renderer();

  // Uploads `mesh` with its triangles in the order that suits the GPU (optimizeDrawOrder: the
  // one place every mesh is reordered), and, above kLightProxyMinTriangles, a simplified copy
  // for the light's pass (render/mesh_detail.h). Keeps the reordered mesh on the CPU for the
  // interaction copy, made at its first use.
  void setMesh(const Mesh& mesh);
  bool hasMesh() const { return mesh_ && !mesh_->empty(); }
  size_t triangleCount() const { return mesh_ ? mesh_->triangleCount() : 0; }

  // Off: setMesh keeps the file's triangle order (for comparisons; on by default). Applies to
  // the next setMesh.
  void setDrawOrderOptimized(bool optimized) { drawOrderOptimized_ = optimized; }

  // The light's pass from a proxy (on by default; off: the full mesh, for comparisons). Takes
  // effect at once (the light's map is redrawn).
  void setLightProxyEnabled(bool enabled);
  bool lightProxyEnabled() const { return lightProxyEnabled_; }
  // Triangles the light's pass draws, and meshoptimizer's bound on how far its surface lies
  // from the mesh's (scene units; 0 without a proxy).
  size_t lightTriangleCount() const;
  float lightProxyErrorUnits() const { return lightProxyErrorUnits_; }
  // The proxy made on a worker thread (the viewer: 2.3 s for a 1.6 M-triangle mesh, which would
  // freeze the window): setMesh returns at once and the light's pass draws the full mesh until the
  // proxy is there; the first render() after that takes it and re-runs every pass (isCurrent() is
  // false from the moment it is ready), so each still frame from then on is exactly what a
  // renderer that made the proxy in setMesh draws. Off by default (the CLI, tests, benchmarks:
  // every frame the same). Applies from the next setMesh.
  void setLightProxyInBackground(bool background) { lightProxyInBackground_ = background; }
  bool lightProxyPending() const { return lightProxyJob_.has_value(); }
  // The same for the further bounces' form factors (`marble`, further_radiosity.h): in the
  // background, the first `marble` frame once the proxy is there (or at once without one) starts
  // them on a worker thread (0.3-1 s), the frames until they are there have no further bounces, and
  // the first render() after that takes them and re-runs every pass (isCurrent() is false from the
  // moment they are ready).
  bool furtherBouncesPending() const { return furtherJob_.has_value(); }
  // Waits for a pending proxy and takes it now (GL context current), and has the next `marble`
  // frame make the further bounces (or wait for them) before it draws: that frame is a finished
  // one, as a renderer's that works in the foreground (the viewer's scripted screenshot).
  void waitForBackgroundWork();

  // Which mesh the camera's passes (geometry, floor) draw: the full mesh, or -- while the view
  // moves -- the interaction copy (at most about kInteractionTriangles, render/mesh_detail.h:
  // the light's proxy where that is small enough, else made at the first request for this mesh;
  // a mesh without a proxy and no larger than that is its own copy). Changing it
  // re-runs the camera's passes, so the first Full frame after Interaction ones is exactly
  // what a fresh renderer draws. The light's pass is not affected (its maps: setLightMapDetail).
  enum class MeshDetail { Full, Interaction };
  void setMeshDetail(MeshDetail detail);
  MeshDetail meshDetail() const { return detail_; }
  size_t interactionTriangleCount();  // makes the copy if needed

  // Dynamic resolution (interaction detail for the screen passes, as game engines and scan
  // viewers do it): every pass draws at `scale` of the target's width and height (rounded, at
  // least 1 pixel) and the finished frame is stretched to the target bilinearly. 1 (default):
  // full resolution. The viewer lowers it while the camera, the object or the light moves and
  // sets 1 on the first still frame, which then is exactly what a fresh renderer draws: every
  // pass that reads the frame size re-runs at the full size (PassInput::FrameSize). Clamped to
  // [kMinResolutionScale, 1].
  void setResolutionScale(float scale);
  float resolutionScale() const { return resolutionScale_; }
  static constexpr float kMinResolutionScale = 0.25f;

  // Interaction detail for the light's maps (LightDepthPass): Interaction -- while the object or
  // the light moves, when the light's pass re-runs every frame anyway -- draws them at the
  // resolution scale's share of their full width (512² of 1024² at 0.5), so that a light texel
  // covers as many of the reduced frame's pixels as of the full frame's (shadow edges, the
  // thickness's steps and the bounce's texels stay as coarse as the frame around them); at scale
  // 1 it is the full size. Full (default): the full size always. A change of the size re-runs the
  // light's pass and every pass that reads its maps, and the full-size maps are never drawn at
  // another size: the first Full (or scale 1) frame after Interaction ones is exactly what a
  // fresh renderer draws. The viewer keeps Full while only the camera moves: its light's maps
  // are current then and are not redrawn at all.
  enum class LightMapDetail { Full, Interaction };
  void setLightMapDetail(LightMapDetail detail);
  LightMapDetail lightMapDetail() const { return lightMapDetail_; }
  int lightMapSize() const;  // the width of the light's depth map the next frame draws and reads
  // Triangles the light's pass draws into maps of lightMapSize(): below the full size, where there
  // is a proxy, a coarser copy of it within half of that size's texel (made here if needed).
  size_t lightMapTriangleCount();

  // The environment map used when a scene says "environment": "map" (uploaded here, once; the
  // precomputation is the caller's, before any GL: see loadEnvironmentMap). Without one, such
  // a scene gets no environment light.
  void setEnvironmentMap(const PrefilteredEnvironment& environment);
  void clearEnvironmentMap();

  // Which frame a caller's target holds: what render() returned when it drew into it. Serials
  // come from one process-wide counter and are never reused, unlike GL names (gl/borrowed.h): a
  // new target that gets a deleted one's name still holds no token, so it is never current.
  class FrameToken {
  public:
    FrameToken() = default;  // holds no frame: never current
    bool operator==(const FrameToken&) const = default;

  private:
    friend class Renderer;
    explicit FrameToken(uint64_t serial) : serial_(serial) {}
    uint64_t serial_ = 0;
  };

  // Renders `scene` (its mesh must have been set) into `targetFbo` of the given size, and
  // returns the token of the frame now in it (an empty token when nothing was drawn: no mesh,
  // an empty size).
  FrameToken render(const Scene& scene, const glm::mat4& model, GLuint targetFbo, int width, int height);

  // The last frame's linear HDR image (before tone mapping), top row first, with coverage as
  // alpha (1 on the object, 0 on the background). Not for `floor`. Re-runs the last frame's
  // post pass into a float target.
  ImageRGBF readHdr();

  // GPU times of the last frame's passes; `wait` blocks until they are known.
  PassTimes passTimes(bool wait = false);
  // Bytes of GL textures and buffers the renderer allocated.
  size_t glBytes() const;
  // Texels of the `marble` bounce's refined grid gathered at the last bounce pass (BouncePass: where
  // the coarse grid's samples do not continue the surface). Reads the count back (waits for the GPU).
  int bounceRefinedTexels() const;
  // For tests: whether the `marble` bounce pass's draws skip the background by the depth test
  // (BouncePass::setSkipsBackground; on by default).
  void setBounceSkipsBackground(bool on);
  // For tests: whether the geometry pass culls the faces no camera ray meets first
  // (GeometryPass::setCullsHiddenFaces; on by default).
  void setGeometryCullsHiddenFaces(bool on);
  // For tests: whether the geometry pass drops on the CPU the triangles GL's culling would
  // discard (GeometryPass::setCullsOnCpu, render/screen_cull.h; on by default where GL rasterizes
  // in software, gl/software_rasterizer.h).
  void setGeometryCullsOnCpu(bool on);
  // For tests: whether the light-depth pass's depth map and reflective shadow map cull the faces
  // no ray from the light meets first (LightDepthPass::setCullsHiddenFaces; on by default).
  void setLightCullsHiddenFaces(bool on);

  // Whether a target that holds frame `shown` (render()'s token; the caller keeps it with its
  // target) still holds what render() would draw now: `shown` is the last frame drawn, of this
  // scene, model and size, and nothing the frame depends on changed since (mesh, environment
  // map, shaders, settings). A caller whose target keeps its content between frames (the
  // viewer's view image, the benchmark's target) skips render() then: an unchanged frame runs
  // no pass at all. The caller drops its token (an empty one) when it makes a new target or
  // draws into it by other means. The target's GL name is not compared: GL reuses names.
  bool isCurrent(const Scene& scene, const glm::mat4& model, FrameToken shown, int width, int height) const {
    return lastOutput_ &&
           *lastOutput_ == OutputKey{scene, model, shown, width, height, cache_.stateRevision(), resolutionScale_} &&
           !(lightProxyJob_ && lightProxyJob_->ready()) && !(furtherJob_ && furtherJob_->ready());
  }
  // The post pass's picture of the last frame (RGBA8; luma in alpha when FXAA is on), before
  // antialiasing: for tests and tools.
  GLuint displayImageTexture() const { return displayImage_ ? displayImage_->texture() : 0; }
  // Forget every cached output (the next frame runs every pass).
  void invalidate();

  // Off: the pattern's turbulence is evaluated per pixel even where a baked grid would give the
  // same picture (turbulence_texture.h); for comparisons. On by default.
  void setTurbulenceGridEnabled(bool enabled);

  // Rebuilds every program from the library's sources. On a compile error the previous
  // programs stay in use and gl::ShaderError is thrown (its message names file and line).
  void reloadShaders();

private:
  struct Passes;
  ShaderLibrary shaders_;
  std::unique_ptr<Passes> passes_;
  std::optional<GpuMesh> mesh_;
  Mesh cpuMesh_;                          // the reordered mesh, for the simplified copies
  // The further bounces' form factors (`marble`), from the light's proxy where there is one: made
  // at the first `marble` frame after setMesh (or a new proxy);
  // solved again (the bounce pass's grid) at the first `marble` frame after the light's pass ran.
  std::unique_ptr<FurtherRadiosity> further_;
  bool furtherStale_ = true;
  std::optional<BackgroundJob<std::unique_ptr<FurtherRadiosity>>> furtherJob_;  // being made (the viewer)
  bool furtherInForeground_ = false;  // waitForBackgroundWork: the next frame makes them at once
  std::optional<GpuMesh> lightMesh_;      // the light's proxy; empty: the light draws mesh_
  Mesh lightProxyMesh_;                   // its CPU copy (empty without), for the interaction copy
  float lightProxyErrorUnits_ = 0.0f;
  bool lightProxyEnabled_ = true;
  bool lightProxyInBackground_ = false;
  std::optional<BackgroundSimplification> lightProxyJob_;  // the proxy being made
  bool drawOrderOptimized_ = true;
  std::optional<GpuMesh> interactionMesh_;  // made at the first Interaction request
  bool interactionIsFull_ = false;          // the mesh is small enough to be its own copy
  bool interactionIsLightProxy_ = false;    // the light's proxy is small enough to be the copy
  MeshDetail detail_ = MeshDetail::Full;
  LightMapDetail lightMapDetail_ = LightMapDetail::Full;
  // Sets the light pass's map size from lightMapDetail_ and resolutionScale_; a change makes the
  // light's pass stale (PassInput::LightMesh).
  void updateLightMapSize();
  void makeLightProxy();
  void useLightProxy(SimplifiedMesh proxy);
  void adoptLightProxy(bool wait);  // takes a finished (or, with wait, the pending) proxy
  void forgetFurtherBounces();      // a new mesh or proxy: none until made again
  void makeFurtherBounces();        // at a `marble` frame: made, started in the background, or waiting for the proxy
  void adoptFurtherBounces();       // takes finished background ones
  const GpuMesh& cameraMesh();
  const GpuMesh& lightMesh() const { return lightMesh_ ? *lightMesh_ : *mesh_; }
  // What the light's pass draws into maps of `mapSize`: at the full size lightMesh(); smaller, where
  // there is a proxy, a coarser copy of it (made at its first use for that size), whose collapses
  // stay within half of that size's texel, as the proxy's within half of the full size's.
  std::optional<GpuMesh> reducedLightMesh_;
  int reducedLightMeshSize_ = 0;
  const GpuMesh& lightMeshFor(int mapSize);
  OccupancyGrid meshCells_;  // for the spans FXAA draws (screen_tiles.h)
  // FXAA's spans (the whole frame for views that are not of the mesh), made once per view
  // (model-view-projection and size).
  std::vector<ScreenRect> aaSpans_;
  glm::mat4 aaSpansMvp_{0.0f};
  int aaSpansWidth_ = 0, aaSpansHeight_ = 0;
  bool aaSpansWholeFrame_ = false;
  const std::vector<ScreenRect>& aaSpans(const glm::mat4& mvp, int width, int height, bool wholeFrame);
  std::optional<EnvironmentMap> environment_;
  TurbulenceTexture turbulence_;  // the pattern's baked turbulence, kept across shader reloads
  PassTimes times_;
  PassCache cache_;  // what each cached pass's output was made from
  // What the post pass's stored diffuse part (`marble`) was made from: the generations of
  // kStoredDiffuseReads' passes when it was written.
  std::optional<PerPass<uint64_t>> storedDiffuse_;
  // What a `marble` frame's reflected and upsampled blurred light are made from: the frame's
  // values (compared by sameButPattern), the passes' outputs (by generation, the albedo's aside)
  // and the renderer's state (by revision).
  struct SurfaceKey {
    FrameInputs inputs;
    PerPass<uint64_t> generations;
    uint64_t stateRevision = 0;
    bool same(const SurfaceKey& o) const;
  };
  std::optional<SurfaceKey> lastSurface_;    // the last `marble` frame's
  std::optional<SurfaceKey> storedSurface_;  // the post pass's stored surface textures' (SurfaceReuse)
  // What the last frame drew: a caller holding its token, with the same inputs, draws nothing.
  struct OutputKey {
    Scene scene;
    glm::mat4 model{1.0f};
    FrameToken frame;  // never empty here
    int width = 0, height = 0;
    uint64_t stateRevision = 0;  // PassCache::stateRevision
    float resolutionScale = 1.0f;
    bool operator==(const OutputKey&) const = default;
  };
  std::optional<OutputKey> lastOutput_;  // empty: no frame is current
  // The last frame that ran the passes (not `floor`), for readHdr.
  std::optional<FrameInputs> lastFrame_;
  ScreenRect lastRect_{};
  std::optional<OffscreenTarget> hdrReadback_;

  float resolutionScale_ = 1.0f;
  std::optional<OffscreenTarget> reducedFrame_;  // the frame at resolutionScale_, before stretching
  // One frame at the size the passes draw (render() stretches it when the scale is below 1).
  FrameToken drawFrame(const Scene& scene, const glm::mat4& model, GLuint targetFbo, int width, int height);
  // Where the last drawFrame wrote anything but the flat background (its pixels); empty: it may
  // have content anywhere (the floor, the light's map, a stage).
  std::optional<ScreenRect> contentRect_;
  // reducedFrame_ stretched to the caller's target (bilinear), only where it has content.
  void stretchReducedFrame(const Scene& scene, GLuint targetFbo, int width, int height);

  PostInputs postInputs() const;
  PassTimer& timerOf(Pass p);
  void invalidateStage();
  // The copy the camera's passes draw was remade: their inputs changed if they draw it.
  void interactionCopyRemade();
  // `target`, (re)made at this size and format, with the G-buffer's depth attached.
  OffscreenTarget& surfaceTarget(std::optional<OffscreenTarget>& target, int width, int height, GLenum format);
  const EnvironmentMap* environment() const { return environment_ ? &*environment_ : nullptr; }
  // The post pass writes this display image (with the G-buffer's depth, so it shades only the
  // surface); FXAA, or a copy, takes it to the target.
  std::optional<OffscreenTarget> displayImage_;
};

}  // namespace marble
