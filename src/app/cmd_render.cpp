#include "cmd_render.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/core/image_downsample.h"
#include "marble/core/png_text.h"
#include "marble/environment/environment_lighting.h"
#include "marble/gl/headless_context.h"
#include "marble/render/offscreen_target.h"
#include "marble/render/renderer.h"
#include "marble/scene/scene_io.h"
#include "render_turntable.h"
#include "video_encode.h"
#include "shader_source.h"

namespace marble {
namespace {

std::string encodeHdrOutput(const std::string& path, const ImageRGBF& image) {
  try {
    return encodeExr(image);
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot encode EXR: ") + e.what());
  }
}

// --quality final: what a finished still needs and an interactive frame cannot afford.
// Returns the supersampling factor.
int applyQuality(const RenderOptions& o, Scene& scene) {
  if (o.quality == "draft") return o.supersample > 0 ? o.supersample : 1;
  if (o.quality != "final") throw InputError("--quality", "", "expected draft or final, got \"" + o.quality + "\"");
  scene.render.subsurface_resolution = SubsurfaceResolution::Full;
  scene.render.antialias = Antialias::None;  // the supersampling antialiases, without FXAA's blur
  if (o.supersample > 0) return o.supersample;
  const int largest = std::max(scene.render.width, scene.render.height);
  return std::clamp(kMaxRenderSize / largest, 1, 3);
}

void checkTurntable(const RenderOptions& o) {
  if (!o.turntable) {
    if (!o.video.empty()) throw InputError("--video", "", "needs --turntable N (the frames to encode)");
    return;
  }
  if (*o.turntable < 1 || *o.turntable > 3600)
    throw InputError("--turntable", "", "expected 1 to 3600 frames, got " + std::to_string(*o.turntable));
  if (o.turntableOf != "object" && o.turntableOf != "light")
    throw InputError("--turntable-of", "", "expected object or light, got \"" + o.turntableOf + "\"");
  if (o.fps < 1 || o.fps > 120) throw InputError("--fps", "", "expected 1 to 120 frames per second, got " + std::to_string(o.fps));
  if (o.output.size() >= 4 && o.output.substr(o.output.size() - 4) == ".png")
    throw InputError("-o", o.output, "--turntable writes numbered frames into a folder: give -o a folder (e.g. -o frames/)");
  if (!o.video.empty()) checkVideoOutput(o.video);  // before any frame: a missing ffmpeg is said at once
}

}  // namespace

int runRenderCommand(const RenderOptions& o) {
  return reportErrors("render", [&] {
    // The scene is read first, so a broken scene is reported even when -o was forgotten.
    Scene scene = buildScene(o.scene);
    const int n = applyQuality(o, scene);
    if (o.output.empty()) throw InputError("-o", "", "an output file is required (e.g. -o out.png)");
    checkTurntable(o);
    // Supersampling renders the whole frame n times larger; the size limit is on what is rendered.
    const int width = scene.render.width * n, height = scene.render.height * n;
    if (width > kMaxRenderSize || height > kMaxRenderSize)
      throw InputError("--supersample", "",
                       std::to_string(n) + " times " + std::to_string(scene.render.width) + "x" +
                           std::to_string(scene.render.height) + " is " + std::to_string(width) + "x" +
                           std::to_string(height) + ", above the limit of " + std::to_string(kMaxRenderSize) +
                           " pixels a side; lower --supersample or the size");
    if (!o.hdr.empty() && scene.render.mode == RenderMode::Floor)
      throw InputError("--hdr", "", "the floor mode has no HDR image");
    const Mesh mesh = loadSceneMesh(scene);
    const auto environment = loadSceneEnvironment(scene);  // a bad map fails here, before any GL
    if (environment && o.timings)
      std::printf("environment map %s: %d x %d, read and prefiltered in %.2f s\n", environment->source.c_str(),
                  environment->sourceWidth, environment->sourceHeight, environment->seconds);
    ShaderLibrary shaders = shaderLibraryFor(false);
    HeadlessContext context;
    Renderer renderer(std::move(shaders));
    // One picture evaluates the pattern once: baking the turbulence grid (0.36 s for 256^3)
    // would cost more than it saves. The picture is the same within rounding.
    renderer.setTurbulenceGridEnabled(false);
    renderer.setMesh(mesh);
    if (environment) renderer.setEnvironmentMap(*environment);
    if (o.turntable) {
      renderTurntable(renderer, scene, {*o.turntable, o.turntableOf == "light", o.output, n, o.fps, o.video});
      return 0;
    }
    OffscreenTarget target(width, height);
    if (o.timings) {
      // A first frame pays llvmpipe's lazy shader compilation and its first timer query is
      // unreliable; time a second, full frame instead.
      renderer.render(scene, glm::mat4(1.0f), target.fbo(), target.width(), target.height());
      renderer.passTimes(true);
      renderer.invalidate();
    }
    renderer.render(scene, glm::mat4(1.0f), target.fbo(), target.width(), target.height());
    const ImageRGBA8 image = downsampleSrgb(target.read(), n);
    if (GLenum err = glGetError(); err != GL_NO_ERROR) {
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04x", err);
      throw EnvironmentError(std::string("OpenGL error ") + hex + " while rendering");
    }
    // The PNG and the EXR appear together or not at all: both are written to temporaries, and
    // only when both are complete are they renamed into place (docs/reliability.md).
    AtomicFileSet outputs;
    // The scene rides along (paths relative to the picture): `marble render shot.png` re-renders it.
    outputs.add(o.output, insertPngText(encodePng(image), kPngSceneKeyword, sceneToJsonText(scene, o.output)));
    if (!o.hdr.empty()) outputs.add(o.hdr, encodeHdrOutput(o.hdr, downsampleLinear(renderer.readHdr(), n)));
    outputs.commit();
    if (!o.hdr.empty()) std::cout << "wrote " << o.hdr << " (linear, not tone-mapped)\n";
    if (o.timings) {
      const PassTimes t = renderer.passTimes(true);
      std::printf("pass             GPU ms\n");
      for (const PassDecl& d : passList())
        if (passInFrame(d.pass, scene)) std::printf("%-16s %7.2f\n", d.name, t.ms[d.pass]);
    }
    std::cout << "wrote " << o.output << " (" << scene.render.width << "x" << scene.render.height << ", "
              << renderModeName(scene.render.mode) << ", " << mesh.triangleCount() << " triangles";
    if (n > 1) std::cout << ", supersampled " << n << "x" << n;
    if (o.quality == "final") std::cout << ", final quality";
    std::cout << ")\n";
    return 0;
  });
}

}  // namespace marble
