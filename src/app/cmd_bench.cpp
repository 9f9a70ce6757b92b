#include "cmd_bench.h"

#include <algorithm>

#include "bench_clock.h"
#include "bench_motion.h"
#include "bench_report.h"
#include "marble/core/error.h"
#include "marble/core/memory_usage.h"
#include "marble/environment/environment_lighting.h"
#include "marble/gl/headless_context.h"
#include "marble/render/offscreen_target.h"
#include "marble/render/renderer.h"
#include "shader_source.h"

namespace marble {

namespace {

constexpr int kMaxFrames = 100000;

// Ranges are checked here, not by CLI11, so a bad value is one line and exit code 2 like
// every other bad input.
void validate(const BenchOptions& o) {
  if (o.frames < 1 || o.frames > kMaxFrames)
    throw InputError("--frames", "", "expected 1 to " + std::to_string(kMaxFrames) + ", got " + std::to_string(o.frames));
  if (o.warmup < 0 || o.warmup > kMaxFrames)
    throw InputError("--warmup", "", "expected 0 to " + std::to_string(kMaxFrames) + ", got " + std::to_string(o.warmup));
}

std::string glString(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}

// The passes a frame of these settings runs, in order. The subsurface blur (and its depth
// buffer, at half resolution) exists only for `marble`, FXAA only when antialiasing is on; the
// floor mode is one pass and nothing else.
std::vector<PassSeries> emptySeries(const RenderSettings& settings) {
  if (settings.mode == RenderMode::Floor) return {PassSeries{"floor", {}, 0, {}}};
  // `marble` has no albedo pass: its post pass evaluates the pattern when it changed
  // (post_diffuse_sources counts how often).
  const bool marble = settings.mode == RenderMode::Marble;
  std::vector<PassSeries> s = {{"light_depth", {}, 0, {}}, {"geometry", {}, 0, {}}};
  if (!marble) s.push_back({"albedo", {}, 0, {}});
  if (marble && settings.subsurface_resolution == SubsurfaceResolution::Half) s.push_back({"blur_depth", {}, 0, {}});
  s.push_back({"lighting", {}, 0, {}});
  if (marble) s.push_back({"subsurface_blur", {}, 0, {}});
  s.push_back({"post", {}, 0, {}});
  if (settings.antialias == Antialias::Fxaa) s.push_back({"fxaa", {}, 0, {}});
  return s;
}

// A cached pass did not run this frame: it costs 0, whatever its timer still remembers. The
// post pass and FXAA run whenever anything changed (a frame with no change draws nothing).
void recordPasses(std::vector<PassSeries>& series, const PassTimes& t) {
  for (auto& p : series) {
    double ms = 0;
    bool ran = true;
    if (p.name == "floor") ran = t.floorRan, ms = t.floorMs;
    if (p.name == "lighting") ran = t.lightingRan, ms = t.lightingMs;
    if (p.name == "subsurface_blur") ran = t.lightingRan, ms = t.subsurfaceBlurMs;
    if (p.name == "post") ran = t.postRan, ms = t.postMs;
    if (p.name == "fxaa") ran = t.fxaaRan, ms = t.fxaaMs;
    if (p.name == "light_depth") ran = t.lightDepthRan, ms = t.lightDepthMs;
    if (p.name == "geometry") ran = t.geometryRan, ms = t.geometryMs;
    if (p.name == "albedo") ran = t.albedoRan, ms = t.albedoMs;
    if (p.name == "blur_depth") ran = t.blurDepthRan, ms = t.blurDepthMs;
    p.ms.push_back(ran ? ms : 0.0);
    if (ran) {
      ++p.runs;
      p.msWhenRun.push_back(ms);
    }
  }
}

}  // namespace

void addBenchOptions(CLI::App& cmd, BenchOptions& o) {
  addSceneOptions(cmd, o.scene, true);
  o.scene.showcaseWhenEmpty = false;  // the benchmark's built-in scene is fixed: figures stay comparable
  cmd.add_option("--frames", o.frames, "Frames to measure (default 20)");
  cmd.add_option("--warmup", o.warmup, "Frames to render first and not measure (default 3)");
  cmd.add_option("--motion", o.motion, "What changes every frame: none, camera, light, both, params (gloss), scattering, pattern (default none)");
  cmd.add_flag("--json", o.json, "Print one JSON object instead of the table");
  cmd.add_flag("--serial-passes", o.serialPasses,
               "Finish each pass before the next and time it by the wall clock (whole cost of each pass, "
               "vertex work included; frames get slower)");
  cmd.add_option("--turbulence-grid", o.turbulenceGrid,
                 "on (default): the pattern's turbulence read from its baked grid where that is exact; off: "
                 "evaluated per pixel (the same picture within rounding; to compare the two)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--draw-order", o.drawOrder,
                 "optimized (default): triangles reordered for the vertex cache and overdraw at upload; file: "
                 "in the file's order (to compare the two)")
      ->check(CLI::IsMember({"optimized", "file"}));
  cmd.add_option("--light-proxy", o.lightProxy,
                 "on (default): the light's pass draws a simplified copy of a mesh above 60,000 triangles; off: "
                 "the full mesh (to compare)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--interaction-detail", o.interactionDetail,
                 "on: every measured frame draws the camera's passes from the interaction copy (about 100,000 "
                 "triangles), as the viewer does while the view moves; off (default): the full mesh")
      ->check(CLI::IsMember({"on", "off"}));
}

int runBenchCommand(const BenchOptions& o) {
  return reportErrors("bench", [&] {
    validate(o);
    const BenchMotion motion = parseBenchMotion(o.motion);
    const Scene base = buildScene(o.scene);

    BenchResult r;
    r.input = o.scene.input.empty() ? "default scene" : o.scene.input;
    r.width = base.render.width;
    r.height = base.render.height;
    r.mode = renderModeName(base.render.mode);
    r.motion = benchMotionName(motion);
    r.frames = o.frames;
    r.warmup = o.warmup;
    if (o.serialPasses) r.passTiming = "serial";

    double t0 = wallMs();
    const Mesh mesh = loadSceneMesh(base);
    r.loadMs = wallMs() - t0;
    const auto environment = loadSceneEnvironment(base);  // not part of the mesh's load time

    ShaderLibrary shaders = shaderLibraryFor(false);
    HeadlessContext context;
    r.glRenderer = context.renderer();
    r.glVersion = glString(GL_VERSION);
    PassTimer::setSerialized(o.serialPasses);
    Renderer renderer(std::move(shaders));
    renderer.setTurbulenceGridEnabled(o.turbulenceGrid == "on");
    r.turbulenceGrid = o.turbulenceGrid == "on";
    renderer.setDrawOrderOptimized(o.drawOrder == "optimized");
    renderer.setLightProxyEnabled(o.lightProxy == "on");
    t0 = wallMs();
    renderer.setMesh(mesh);
    glFinish();
    r.uploadMs = wallMs() - t0;
    r.triangles = renderer.triangleCount();
    r.drawOrder = o.drawOrder;
    r.lightTriangles = renderer.lightTriangleCount();
    r.lightProxyErrorUnits = renderer.lightProxyErrorUnits();
    if (o.interactionDetail == "on") {
      t0 = wallMs();
      r.interactionTriangles = renderer.interactionTriangleCount();  // made here, outside the frames
      glFinish();
      r.interactionMs = wallMs() - t0;
      renderer.setMeshDetail(Renderer::MeshDetail::Interaction);
    }
    if (environment) renderer.setEnvironmentMap(*environment);
    OffscreenTarget target(r.width, r.height);
    r.passes = emptySeries(base.render);

    const glm::mat4 model(1.0f);
    for (int i = 0; i < o.warmup + o.frames; ++i) {
      const Scene scene = sceneAtFrame(base, motion, i);  // outside the timed part: harness, not renderer
      const double wall0 = wallMs(), thread0 = threadCpuMs(), process0 = processCpuMs();
      // As the viewer does: a frame with nothing changed is not drawn (Renderer::isCurrent).
      const bool drawn = !renderer.isCurrent(scene, model, target.fbo(), r.width, r.height);
      if (drawn) renderer.render(scene, model, target.fbo(), r.width, r.height);
      const double thread1 = threadCpuMs();
      // llvmpipe (like any GPU) works after the calls return; glFinish makes the frame's
      // whole cost land inside the measurement.
      glFinish();
      const double wall1 = wallMs(), process1 = processCpuMs();
      const PassTimes times = drawn ? renderer.passTimes(true) : PassTimes{};  // not drawn: no pass ran
      if (i < o.warmup) continue;
      r.frameMs.push_back(wall1 - wall0);
      r.cpuSubmitMs.push_back(thread1 - thread0);
      r.cpuProcessMs.push_back(process1 - process0);
      recordPasses(r.passes, times);
      if (times.diffuseSource >= 0) ++r.diffuseSources[static_cast<size_t>(times.diffuseSource)];
    }
    if (GLenum err = glGetError(); err != GL_NO_ERROR)
      throw EnvironmentError("OpenGL error " + std::to_string(err) + " while benchmarking");

    r.rssBytes = residentBytes();
    // The two counters are sampled differently by the kernel; a peak below the current
    // value would only confuse.
    r.peakRssBytes = std::max(peakResidentBytes(), r.rssBytes);
    r.glBytes = renderer.glBytes();
    if (o.json)
      printBenchJson(r);
    else
      printBenchTable(r);
    return 0;
  });
}

}  // namespace marble
