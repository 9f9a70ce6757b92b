#include "viewer_actions.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "marble/core/error.h"
#include "marble/scene/material_io.h"
#include "marble/scene/scene_io.h"

namespace marble {
namespace {

std::string joinWarnings(const std::vector<std::string>& warnings) {
  std::string s;
  for (const auto& w : warnings) s += "\nwarning: " + printable(w, kMessageLineLimit);
  return s;
}

void saveMaterialFile(ViewerState& s) {
  Material m = s.scene.material;
  // The file's own name becomes the preset's name, so `--preset FILE` lists it sensibly.
  const std::string stem = std::filesystem::path(s.materialPathInput).stem().string();
  if (!stem.empty()) m.name = stem;
  saveMaterial(s.materialPathInput, m);
  s.setStatus("material saved: " + std::filesystem::absolute(s.materialPathInput).string());
}

void loadMaterialFile(ViewerState& s) {
  std::vector<std::string> warnings;
  const Material m = loadPreset(s.materialPathInput, &warnings);  // throws: nothing changed yet
  s.scene.material = m;
  s.presetName = m.name;
  s.presetMaterial = m;
  s.undo.commit(currentEdit(s));  // loading is one undoable step
  s.setStatus("material loaded: " + s.materialPathInput + joinWarnings(warnings));
}

void saveSceneFile(ViewerState& s) {
  Scene scene = s.scene;
  scene.camera.position = s.camera.position();
  scene.camera.target = s.camera.target;
  scene.light.position = s.light.position();
  saveScene(s.scenePathInput, scene);
  s.setStatus("scene saved: " + std::filesystem::absolute(s.scenePathInput).string());
}

void loadSceneFile(Renderer& renderer, ViewerState& s) {
  std::vector<std::string> warnings;
  const Scene scene = sceneForInput(s.scenePathInput, warnings);  // .json or a marble PNG; throws: nothing changed yet
  const Mesh mesh = loadSceneMesh(scene);                      // likewise
  const auto environment = loadSceneEnvironment(scene);        // likewise
  adoptScene(s, scene);
  adoptMesh(renderer, s, mesh, scene.mesh);
  if (environment) adoptEnvironment(renderer, s, *environment);
  s.meshPathInput = scene.mesh.rfind("builtin:", 0) == 0 ? "" : scene.mesh;
  s.setStatus("scene loaded: " + s.scenePathInput + joinWarnings(warnings));
}

// Runs `action`, turning any error into the panel's red status line.
template <typename F>
void attempt(ViewerState& s, F&& action) {
  try {
    action();
  } catch (const std::exception& e) {
    s.setError(e.what());
  }
}

}  // namespace

EditState currentEdit(const ViewerState& s) {
  return EditState{s.scene.material, s.scene.light, s.light, s.scene.render.mode};
}

void applyEdit(ViewerState& s, const EditState& e) {
  s.scene.material = e.material;
  s.scene.light.type = e.light.type;
  s.scene.light.color = e.light.color;
  s.scene.light.intensity = e.light.intensity;
  s.light = e.lightOrbit;
  s.scene.render.mode = e.mode;
}

void adoptScene(ViewerState& s, const Scene& scene) {
  s.scene = scene;
  s.camera = Orbit::fromPosition(scene.camera.position, scene.camera.target);
  s.light = Orbit::fromPosition(scene.light.position);
  s.initialCamera = s.camera;
  s.initialLight = scene.light;
  s.initialLightOrbit = s.light;
  s.presetName = scene.material.name;
  s.presetMaterial = scene.material;
  s.undo.reset(currentEdit(s));
}

void adoptMesh(Renderer& renderer, ViewerState& s, const Mesh& mesh, const std::string& source) {
  renderer.setMesh(mesh);
  s.scene.mesh = source;
  s.meshUp[source] = s.scene.up;
  s.meshLabel = source;
  s.triangles = mesh.triangleCount();
  s.meshRadius = 0;
  for (const auto& p : mesh.positions) s.meshRadius = std::max(s.meshRadius, glm::length(p));
}

void adoptEnvironment(Renderer& renderer, ViewerState& s, const PrefilteredEnvironment& env) {
  renderer.setEnvironmentMap(env);
  s.scene.render.environment = Environment::Map;
  s.scene.render.environment_map = env.source;
  s.loadedEnvironment = env.source;
  s.environmentPathInput = env.source;
  char info[96];
  std::snprintf(info, sizeof info, "%d x %d, read and prefiltered in %.1f s", env.sourceWidth, env.sourceHeight, env.seconds);
  s.environmentLabel = info;
}

void loadMeshInto(Renderer& renderer, ViewerState& s, const std::string& source) {
  Scene candidate = s.scene;
  candidate.mesh = source;
  // Reloading the same file keeps the up axis the panel just chose; another file gets its own.
  if (source != s.scene.mesh) {
    const auto known = s.meshUp.find(source);
    candidate.up = known != s.meshUp.end() ? known->second : UpAxis::Y;
  }
  const Mesh mesh = loadSceneMesh(candidate);  // throws InputError: the current mesh stays
  s.scene.up = candidate.up;
  adoptMesh(renderer, s, mesh, source);
  s.requestFrame = true;  // a new mesh, or the same one stood up differently: frame it
}

void frameObject(ViewerState& s, float aspect) {
  // The bounding sphere must fit the narrower of the two field-of-view angles.
  const float halfY = glm::radians(s.scene.camera.fov_y_deg) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * std::max(aspect, 0.05f));
  const float half = std::min(halfX, halfY);
  s.camera.target = glm::vec3(0.0f);
  s.camera.distance = std::clamp(1.08f * std::max(s.meshRadius, 0.01f) / std::sin(half), Orbit::kMinDistance,
                                 Orbit::kMaxDistance);
}

void runFileRequests(Renderer& renderer, ViewerState& s) {
  if (std::exchange(s.requestMeshLoad, false)) {
    attempt(s, [&] {
      loadMeshInto(renderer, s, s.meshPathInput);
      s.setStatus("mesh loaded: " + s.meshPathInput);
    });
  }
  if (std::exchange(s.requestEnvironmentLoad, false)) {
    attempt(s, [&] {
      // Read and precomputed aside: a bad file leaves the previous environment in use.
      const PrefilteredEnvironment env = loadEnvironmentMap(s.environmentPathInput);
      adoptEnvironment(renderer, s, env);
      s.setStatus("environment loaded: " + env.source + " (" + s.environmentLabel + ")");
    });
  }
  if (std::exchange(s.requestSaveMaterial, false)) attempt(s, [&] { saveMaterialFile(s); });
  if (std::exchange(s.requestLoadMaterial, false)) attempt(s, [&] { loadMaterialFile(s); });
  if (std::exchange(s.requestSaveScene, false)) attempt(s, [&] { saveSceneFile(s); });
  if (std::exchange(s.requestLoadScene, false)) attempt(s, [&] { loadSceneFile(renderer, s); });
  if (std::exchange(s.requestUndo, false)) {
    if (auto e = s.undo.undo(currentEdit(s))) applyEdit(s, *e);
    else s.setStatus("nothing to undo");
  }
  if (std::exchange(s.requestRedo, false)) {
    if (auto e = s.undo.redo(currentEdit(s))) applyEdit(s, *e);
    else s.setStatus("nothing to redo");
  }
  if (std::exchange(s.requestShaderReload, false)) {
    attempt(s, [&] {
      renderer.reloadShaders();  // on error the last good programs stay in use
      s.setStatus("shaders reloaded");
    });
  }
}

std::string uniqueScreenshotName() {
  const auto t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[64];
  std::strftime(buf, sizeof buf, "marble-%Y%m%d-%H%M%S", std::localtime(&t));
  const std::string base = buf;
  std::string name = base + ".png";
  for (int i = 2; std::filesystem::exists(name); ++i) name = base + "-" + std::to_string(i) + ".png";
  return name;
}

}  // namespace marble
