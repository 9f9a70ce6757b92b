#include "cmd_view.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <iostream>

#include "glfw_window.h"
#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/render/renderer.h"
#include "viewer_state.h"

namespace marble {
namespace {

// Mouse: left drag orbits the camera, Shift+left drag (or right drag) moves the light,
// middle drag pans, the wheel zooms. ImGui gets the mouse when it is over the panel.
struct MouseControl {
  double lastX = 0, lastY = 0;
  bool dragging = false;

  void update(GLFWwindow* w, ViewerState& s) {
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    const bool left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool right = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    const bool middle = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    const bool any = left || right || middle;
    if (any && !dragging && ImGui::GetIO().WantCaptureMouse) return;  // drag started on the panel
    if (any && dragging) {
      const float dx = static_cast<float>(x - lastX), dy = static_cast<float>(y - lastY);
      if ((left && shift) || right) s.light.rotate(-dx * 0.4f, dy * 0.4f);
      else if (left) s.camera.rotate(-dx * 0.4f, dy * 0.4f);
      else if (middle) s.camera.pan(-dx * 0.002f, dy * 0.002f);
    }
    dragging = any;
    lastX = x;
    lastY = y;
  }
};

// Key presses as edges (down this frame, up the last), polled once per frame.
struct KeyEdges {
  static constexpr int kKeys[] = {GLFW_KEY_ESCAPE, GLFW_KEY_F1, GLFW_KEY_SLASH, GLFW_KEY_F12, GLFW_KEY_F, GLFW_KEY_R};
  bool down[sizeof(kKeys) / sizeof(int)] = {};
  bool edge[sizeof(kKeys) / sizeof(int)] = {};
  void update(GLFWwindow* w) {
    for (size_t i = 0; i < std::size(kKeys); ++i) {
      const bool now = glfwGetKey(w, kKeys[i]) == GLFW_PRESS;
      edge[i] = now && !down[i];
      down[i] = now;
    }
  }
  bool pressed(int key) const {
    for (size_t i = 0; i < std::size(kKeys); ++i)
      if (kKeys[i] == key) return edge[i];
    return false;
  }
};

void onScroll(GLFWwindow* w, double dx, double dy) {
  ImGui_ImplGlfw_ScrollCallback(w, dx, dy);
  if (ImGui::GetIO().WantCaptureMouse) return;
  static_cast<ViewerState*>(glfwGetWindowUserPointer(w))->camera.zoom(static_cast<float>(dy));
}

void loadMeshInto(Renderer& renderer, ViewerState& s, const std::string& source) {
  Scene candidate = s.scene;
  candidate.mesh = source;
  const Mesh mesh = loadSceneMesh(candidate);  // throws InputError: the current mesh stays
  renderer.setMesh(mesh);
  s.scene.mesh = source;
  s.meshLabel = source;
  s.triangles = mesh.triangleCount();
}

ImageRGBA8 readWindow(GLFWwindow* w) {
  int fw, fh;
  glfwGetFramebufferSize(w, &fw, &fh);
  ImageRGBA8 img{fw, fh, std::vector<uint8_t>(static_cast<size_t>(fw) * fh * 4)};
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  flipRows(img);
  return img;
}

std::string uniqueScreenshotName() {
  const auto now = std::chrono::system_clock::now();
  const auto t = std::chrono::system_clock::to_time_t(now);
  char buf[64];
  std::strftime(buf, sizeof buf, "marble-%Y%m%d-%H%M%S", std::localtime(&t));
  std::string base = buf;
  std::string name = base + ".png";
  for (int i = 2; std::filesystem::exists(name); ++i) name = base + "-" + std::to_string(i) + ".png";
  return name;
}

}  // namespace

int runViewCommand(const ViewOptions& o) {
  return reportErrors("view", [&] {
    if (!GlfwWindow::displayAvailable())
      throw EnvironmentError("no display (DISPLAY is not set); use `marble render [INPUT] -o out.png` to render without one");
    ViewerState s;
    s.scene = buildScene(o.scene);
    s.devMode = o.dev;
    s.camera = Orbit::fromPosition(s.scene.camera.position, s.scene.camera.target);
    s.light = Orbit::fromPosition(s.scene.light.position);
    s.presetName = s.scene.material.name;
    const int winW = o.scene.width > 0 ? o.scene.width : 1280, winH = o.scene.height > 0 ? o.scene.height : 800;
    GlfwWindow window(winW, winH, "marble");
    GLFWwindow* w = window.handle();
    glfwSetWindowUserPointer(w, &s);
    glfwSwapInterval(1);

    Renderer renderer(ShaderLibrary(o.dev ? std::string(MARBLE_SOURCE_DIR) + "/shaders" : std::string()));
    loadMeshInto(renderer, s, s.scene.mesh);
    s.meshPathInput = s.scene.mesh.rfind("builtin:", 0) == 0 ? "" : s.scene.mesh;

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini littered in the user's folder
    ImGui::StyleColorsDark();
    float xs = 1, ys = 1;
    glfwGetWindowContentScale(w, &xs, &ys);
    ImGui::GetStyle().ScaleAllSizes(xs);
    ImGui::GetIO().FontGlobalScale = xs;
    ImGui_ImplGlfw_InitForOpenGL(w, true);
    ImGui_ImplOpenGL3_Init("#version 450");
    glfwSetScrollCallback(w, onScroll);
    glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
      auto* st = static_cast<ViewerState*>(glfwGetWindowUserPointer(win));
      if (count > 0) {
        st->meshPathInput = paths[0];
        st->requestMeshLoad = true;
      }
    });

    MouseControl mouse;
    KeyEdges keys;
    auto last = std::chrono::steady_clock::now();
    for (int frame = 0; !glfwWindowShouldClose(w) && (o.frames == 0 || frame < o.frames); ++frame) {
      glfwPollEvents();
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      keys.update(w);
      if (!ImGui::GetIO().WantCaptureKeyboard) {
        if (keys.pressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(w, GLFW_TRUE);
        if (keys.pressed(GLFW_KEY_F1) || keys.pressed(GLFW_KEY_SLASH)) s.showHelp = !s.showHelp;
        if (keys.pressed(GLFW_KEY_F12)) s.requestScreenshot = true;
        if (keys.pressed(GLFW_KEY_F)) s.camera = Orbit::fromPosition(Scene{}.camera.position);
        if (keys.pressed(GLFW_KEY_R) && s.devMode) s.requestShaderReload = true;
      }
      mouse.update(w, s);
      drawPanel(s);
      if (s.showHelp) drawHelpOverlay(s);
      ImGui::Render();

      if (s.requestMeshLoad) {
        s.requestMeshLoad = false;
        try {
          loadMeshInto(renderer, s, s.meshPathInput);
          s.setStatus("loaded " + s.meshPathInput);
        } catch (const std::exception& e) {
          s.setError(e.what());
        }
      }
      if (s.requestShaderReload) {
        s.requestShaderReload = false;
        try {
          renderer.reloadShaders();
          s.setStatus("shaders reloaded");
        } catch (const std::exception& e) {
          s.setError(e.what());  // the last good programs stay in use
        }
      }
      s.scene.camera.position = s.camera.position();
      s.scene.camera.target = s.camera.target;
      s.scene.light.position = s.light.position();

      int fw, fh;
      glfwGetFramebufferSize(w, &fw, &fh);
      if (fw > 0 && fh > 0) {  // minimized: nothing to draw into
        renderer.render(s.scene, glm::mat4(1.0f), 0, fw, fh);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fw, fh);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        const bool lastFrame = o.frames > 0 && frame + 1 == o.frames;
        if (s.requestScreenshot || (lastFrame && !o.screenshot.empty())) {
          const std::string path = (lastFrame && !o.screenshot.empty()) ? o.screenshot : uniqueScreenshotName();
          try {
            writePng(path, readWindow(w));
            s.setStatus("screenshot saved: " + std::filesystem::absolute(path).string());
            if (lastFrame) std::cout << "wrote " << path << "\n";
          } catch (const std::exception& e) {
            if (lastFrame) throw;
            s.setError(e.what());
          }
          s.requestScreenshot = false;
        }
      }
      glfwSwapBuffers(w);
      s.passTimes = renderer.passTimes();
      const auto now = std::chrono::steady_clock::now();
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
