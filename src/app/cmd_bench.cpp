#include "cmd_bench.h"

#include <algorithm>

#include "bench_clock.h"
#include "bench_motion.h"
#include "bench_report.h"
#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/core/memory_usage.h"
#include "marble/environment/environment_lighting.h"
#include "marble/gl/headless_context.h"
#include "marble/render/offscreen_target.h"
#include "marble/render/mesh_detail.h"
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

// The passes a frame of this scene has, in the order it runs them (passList, passInFrame):
// e.g. the subsurface blur (and its depth buffer, at half resolution) only for `marble`, FXAA
// only when antialiasing is on, the floor mode one pass and nothing else. `marble` has no
// albedo pass: its post pass evaluates the pattern when it changed (post_diffuse_sources
// counts how often).
std::vector<PassSeries> emptySeries(const Scene& scene) {
  std::vector<PassSeries> s;
  for (const PassDecl& d : passList())
    if (passInFrame(d.pass, scene)) s.push_back({d.pass, d.name, {}, 0, {}});
  return s;
}

// A cached pass did not run this frame: it costs 0, whatever its timer still remembers. The
// post pass and FXAA run whenever anything changed (a frame with no change draws nothing).
void recordPasses(std::vector<PassSeries>& series, const PassTimes& t) {
  for (auto& p : series) {
    const bool ran = t.ran[p.pass];
    const double ms = t.ms[p.pass];
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
  cmd.add_option("--screenshot", o.screenshot,
                 "After the last frame, save it as PNG (a moving frame with --motion: what the interaction "
                 "settings draw)");
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
                 "on (default): the light's pass draws a simplified copy of a mesh above " +
                     std::to_string(kLightProxyMinTriangles) + " triangles; off: the full mesh (to compare)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--interaction-detail", o.interactionDetail,
                 "on: every measured frame draws the camera's passes from the interaction copy (at most about " +
                     std::to_string(kInteractionTriangles) +
                     " triangles), as the viewer does while the view moves; off (default): the full mesh")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--interaction-resolution", o.interactionResolution,
                 "Every measured frame drawn at this fraction of the width and height and stretched to the "
                 "target (Renderer::setResolutionScale), as the viewer does while the view or the light moves; "
                 "1 (default): full resolution")
      ->check(CLI::Range(static_cast<double>(Renderer::kMinResolutionScale), 1.0));
  cmd.add_option("--interaction-light-maps", o.interactionLightMaps,
                 "on: the light's maps drawn at the --interaction-resolution share of their size "
                 "(Renderer::LightMapDetail::Interaction), as the viewer does while the object or the light moves; "
                 "off (default): full size")
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
    renderer.setResolutionScale(o.interactionResolution);
    r.resolutionScale = renderer.resolutionScale();
    if (o.interactionLightMaps == "on") renderer.setLightMapDetail(Renderer::LightMapDetail::Interaction);
    r.lightMapSize = renderer.lightMapSize();
    t0 = wallMs();
    r.lightMapTriangles = renderer.lightMapTriangleCount();  // a reduced maps' copy made here, outside the frames
    r.lightMapMeshMs = wallMs() - t0;
    if (environment) renderer.setEnvironmentMap(*environment);
    OffscreenTarget target(r.width, r.height);
    Renderer::FrameToken shown;  // the frame `target` holds
    r.passes = emptySeries(base);

    const glm::mat4 model(1.0f);
    for (int i = 0; i < o.warmup + o.frames; ++i) {
      const Scene scene = sceneAtFrame(base, motion, i);  // outside the timed part: harness, not renderer
      const double wall0 = wallMs(), thread0 = threadCpuMs(), process0 = processCpuMs();
      // As the viewer does: a frame with nothing changed is not drawn (Renderer::isCurrent).
      const bool drawn = !renderer.isCurrent(scene, model, shown, r.width, r.height);
      if (drawn) shown = renderer.render(scene, model, target.fbo(), r.width, r.height);
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
    if (!o.screenshot.empty()) writePng(o.screenshot, target.read());  // after the measured frames

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
