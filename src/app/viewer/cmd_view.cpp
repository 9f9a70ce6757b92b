// `marble view`: the frame loop. Setup -> poll -> UI -> requests -> render -> swap, teardown in
// reverse; the panel, input and file actions live in their own files.
#include "cmd_view.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cctype>
#include <cstdio>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "export_job.h"
#include "glfw_window.h"
#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/gl/checked_calls.h"
#include "marble/render/offscreen_target.h"
#include "marble/render/renderer.h"
#include "../shader_source.h"
#include "viewer_actions.h"
#include "viewer_input.h"
#include "viewer_state.h"

namespace marble {
namespace {

ImageRGBA8 readWindow(int fw, int fh) {
  ImageRGBA8 img{fw, fh, std::vector<uint8_t>(static_cast<size_t>(fw) * fh * 4)};
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  flipRows(img);
  return img;
}

// HiDPI: ImGui's sizes and font follow the monitor's content scale (GLFW reports it; the
// framebuffer-to-window ratio is handled by the ImGui backend on its own).
void applyUiScale(float scale) {
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.WindowRounding = 0.0f;  // docked panel: square corners meet the window edge
  style.WindowBorderSize = 0.0f;
  style.Colors[ImGuiCol_WindowBg].w = 1.0f;
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  ImGui::GetIO().FontGlobalScale = scale;
}

void installCallbacks(GLFWwindow* w) {
  installScrollZoom(w);
  glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
    auto* st = static_cast<ViewerState*>(glfwGetWindowUserPointer(win));
    if (count > 0) {
      // A Radiance .hdr becomes the environment, a scene or a marble PNG the scene; anything else
      // is tried as a mesh.
      std::string ext = std::filesystem::path(paths[0]).extension().string();
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext == ".hdr") {
        st->environmentPathInput = paths[0];
        st->requestEnvironmentLoad = true;
      } else if (ext == ".json" || ext == ".png") {  // a scene, or a picture marble rendered (its scene)
        st->scenePathInput = paths[0];
        st->requestLoadScene = true;
      } else {
        st->meshPathInput = paths[0];
        st->requestMeshLoad = true;
      }
    }
  });
  glfwSetWindowContentScaleCallback(w, [](GLFWwindow* win, float xs, float) {
    auto* st = static_cast<ViewerState*>(glfwGetWindowUserPointer(win));
    st->contentScale = xs;
    st->contentScaleChanged = true;
  });
}

// The 3D view: the window right of the panel, in framebuffer pixels.
struct ViewRect {
  int x = 0, width = 0, height = 0;
  float aspect() const { return height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f; }
};

ViewRect viewRect(GLFWwindow* w, float panelWidth) {
  int fw, fh, ww, wh;
  glfwGetFramebufferSize(w, &fw, &fh);
  glfwGetWindowSize(w, &ww, &wh);
  const float toFb = ww > 0 ? static_cast<float>(fw) / static_cast<float>(ww) : 1.0f;
  const int x = std::min(fw, static_cast<int>(std::lround(panelWidth * toFb)));
  return {x, fw - x, fh};
}

// The scene as drawn this frame: the orbits, plus the turntable's transient angle.
Scene frameScene(const ViewerState& s) {
  Scene scene = s.scene;
  scene.camera.position = s.camera.position();
  scene.camera.target = s.camera.target;
  Orbit light = s.light;
  if (s.turntable == Turntable::Light) light.yaw_deg += s.turntableAngle;
  scene.light.position = light.position();
  return scene;
}

glm::mat4 modelMatrix(const ViewerState& s) {
  if (s.turntable != Turntable::Object) return glm::mat4(1.0f);
  return glm::rotate(glm::mat4(1.0f), glm::radians(s.turntableAngle), glm::vec3(0, 1, 0));
}

}  // namespace

static Turntable parseTurntable(const std::string& name) {
  if (name == "off") return Turntable::Off;
  if (name == "object") return Turntable::Object;
  if (name == "light") return Turntable::Light;
  throw InputError("--turntable", "", "expected off, object or light, got \"" + name + "\"");
}

int runViewCommand(const ViewOptions& o) {
  return reportErrors("view", [&] {
    ViewerState s;
    s.turntable = parseTurntable(o.turntable);
    if (!std::isfinite(o.turntableSpeed) || std::abs(o.turntableSpeed) > 3600.0f) {
      char got[32];
      std::snprintf(got, sizeof got, "%g", static_cast<double>(o.turntableSpeed));
      throw InputError("--turntable-speed", "", std::string("expected -3600 to 3600 degrees per second, got ") + got);
    }
    s.turntableDegPerSec = o.turntableSpeed;
    s.interactionDetail = parseInteractionDetail(o.interactionDetail);
    s.interactionResolution = parseInteractionResolution(o.interactionResolution);
    s.interactionLightMaps = o.interactionLightMaps == "on";  // checked by the CLI
    adoptScene(s, buildScene(o.scene));  // a bad scene file fails here, before any window
    s.devMode = o.dev;
    const Mesh firstMesh = loadSceneMesh(s.scene);  // a bad mesh: one line, exit 2, no window flashes up
    ShaderLibrary shaders = shaderLibraryFor(o.dev);  // a bad MARBLE_SHADER_DIR: the same
    const auto firstEnvironment = loadSceneEnvironment(s.scene);  // likewise a bad .hdr
    if (!GlfwWindow::displayAvailable())
      throw EnvironmentError("no display (DISPLAY is not set); use `marble render [INPUT] -o out.png` to render without one");
    const int winW = o.scene.width > 0 ? o.scene.width : 1280, winH = o.scene.height > 0 ? o.scene.height : 800;
    GlfwWindow window(winW, winH, "marble");
    GLFWwindow* w = window.handle();
    glfwSetWindowUserPointer(w, &s);
    glfwSwapInterval(s.vsync ? 1 : 0);
    bool vsyncApplied = s.vsync;

    Renderer renderer(std::move(shaders));
    // A large mesh's light proxy is made while the window already draws the full mesh.
    renderer.setLightProxyInBackground(true);
    adoptMesh(renderer, s, firstMesh, s.scene.mesh);
    if (firstEnvironment) adoptEnvironment(renderer, s, *firstEnvironment);
    s.meshPathInput = s.scene.mesh.rfind("builtin:", 0) == 0 ? "" : s.scene.mesh;

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini littered in the user's folder
    float yscale = 1;
    glfwGetWindowContentScale(w, &s.contentScale, &yscale);
    applyUiScale(s.contentScale);
    ImGui_ImplGlfw_InitForOpenGL(w, true);
    ImGui_ImplOpenGL3_Init("#version 450");
    installCallbacks(w);

    std::optional<OffscreenTarget> view;  // the 3D view's image, blitted right of the panel
    Renderer::FrameToken viewFrame;       // the frame `view` holds (none in a new one)
    BackgroundExport exportJob;  // the Export section's bake: CPU only, on its own thread; cancelled and joined on exit
    MouseControl mouse;
    KeyEdges keys;
    InteractionDetailTracker detail;
    auto last = std::chrono::steady_clock::now();
    for (int frame = 0; !glfwWindowShouldClose(w) && (o.frames == 0 || frame < o.frames); ++frame) {
      glfwPollEvents();
      if (std::exchange(s.contentScaleChanged, false)) applyUiScale(s.contentScale);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      const ViewRect rect = viewRect(w, s.panelWidth);
      keys.update(w);
      handleShortcuts(w, keys, s, rect.aspect());
      mouse.update(w, s);
      drawPanel(s);
      if (s.showHelp) drawHelpOverlay(s);
      // An edit ends when no widget is held and no drag is on: one undo step per gesture.
      if (!ImGui::IsAnyItemActive() && !mouse.dragging()) s.undo.commit(currentEdit(s));
      ImGui::Render();

      runFileRequests(renderer, s);  // first: a mesh loaded now is framed below, before it is drawn
      if (std::exchange(s.requestFrame, false)) frameObject(s, rect.aspect());
      updateExport(exportJob, s);
      if (s.vsync != vsyncApplied) {
        glfwSwapInterval(s.vsync ? 1 : 0);
        vsyncApplied = s.vsync;
      }

      const auto now = std::chrono::steady_clock::now();
      const float dt = std::chrono::duration<float>(now - last).count();
      if (s.turntable != Turntable::Off)
        s.turntableAngle = std::fmod(s.turntableAngle + s.turntableDegPerSec * std::min(dt, 0.1f), 360.0f);

      int fw, fh;
      glfwGetFramebufferSize(w, &fw, &fh);
      if (fw <= 0 || fh <= 0) {  // minimized: nothing to draw into; do not spin the CPU either
        glfwWaitEventsTimeout(0.1);
        last = now;
        continue;
      }
      const ViewRect r = viewRect(w, s.panelWidth);  // this frame's panel width
      bool viewDrawn = false;
      if (r.width > 0) {
        if (!view || view->width() != r.width || view->height() != r.height) {
          view.emplace(r.width, r.height);
          viewFrame = {};
        }
        // The view image keeps its content: an unchanged frame (nothing moved or edited) is not
        // drawn again, and an idle viewer costs no rendering.
        const Scene scene = frameScene(s);
        const glm::mat4 model = modelMatrix(s);
        const InteractionFrame moving =
            detail.next(s.interactionDetail, s.interactionResolution, s.interactionLightMaps, renderer.triangleCount(),
                        scene.camera, scene.light, model);
        renderer.setMeshDetail(moving.mesh);
        renderer.setResolutionScale(moving.resolutionScale);
        renderer.setLightMapDetail(moving.lightMaps);
        // A scripted screenshot (--frames N --screenshot) shows the finished picture, light proxy
        // included, whatever the machine's speed.
        if (o.frames > 0 && frame + 1 == o.frames && !o.screenshot.empty()) renderer.waitForBackgroundWork();
        viewDrawn = !renderer.isCurrent(scene, model, viewFrame, r.width, r.height);
        if (viewDrawn) viewFrame = renderer.render(scene, model, view->fbo(), r.width, r.height);
      }
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, fw, fh);
      const glm::vec3 bg = s.scene.render.background;
      glClearColor(bg.r, bg.g, bg.b, 1.0f);
      gl::clearBound(GL_COLOR_BUFFER_BIT);
      if (r.width > 0)
        gl::blitFramebuffer(view->fbo(), 0, 0, 0, r.width, r.height, r.x, 0, r.x + r.width, r.height,
                            GL_COLOR_BUFFER_BIT, GL_NEAREST);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

      const bool lastFrame = o.frames > 0 && frame + 1 == o.frames;
      if (s.requestScreenshot || (lastFrame && !o.screenshot.empty())) {
        const std::string path = (lastFrame && !o.screenshot.empty()) ? o.screenshot : uniqueScreenshotName();
        try {
          writePng(path, readWindow(fw, fh));
          s.lastScreenshot = std::filesystem::absolute(path).string();
          s.setStatus("screenshot saved: " + s.lastScreenshot);
          if (lastFrame) std::cout << "wrote " << path << "\n";
        } catch (const std::exception& e) {
          if (lastFrame) throw;  // the command line asked for it: fail loudly
          s.setError(e.what());
        }
        s.requestScreenshot = false;
      }
      glfwSwapBuffers(w);
      // An undrawn frame ran no pass (the panel says "cached" for each).
      s.passTimes = viewDrawn ? renderer.passTimes() : PassTimes{};
      s.frameMs.push_back(std::chrono::duration<float, std::milli>(now - last).count());
      if (s.frameMs.size() > 120) s.frameMs.pop_front();
      last = now;
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
  });
}

}  // namespace marble
