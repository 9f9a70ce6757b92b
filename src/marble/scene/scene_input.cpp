// Where a scene comes from (a scene file, a marble PNG, a bare mesh path) and its mesh loaded
// with the scene's options. Reading and writing the scene's JSON: scene_io.cpp.
#include <cctype>
#include <iostream>

#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/core/message_text.h"
#include "marble/scene/scene.h"
#include "marble/scene/scene_io.h"

namespace marble {

Scene sceneForInput(const std::string& input, std::vector<std::string>& warnings) {
  if (input.empty()) return Scene{};
  std::filesystem::path p(input);
  std::string ext = p.extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".json") return loadScene(p, warnings);
  if (ext == ".png") {
    const auto text = readPngText(p, kPngSceneKeyword);
    if (!text) throw InputError(input, "", "carries no marble scene (only PNGs written by `marble render` do)");
    return loadSceneText(*text, p, warnings);
  }
  Scene scene;
  scene.mesh = input;
  return scene;
}

Mesh loadSceneMesh(const Scene& scene, std::vector<std::string>* warnings) {
  if (scene.mesh.rfind("builtin:", 0) == 0) return builtinMesh(scene.mesh.substr(8));
  const bool fromSceneFile = !scene.origin.file.empty() && scene.origin.mesh == scene.mesh;
  std::vector<std::string> local;
  MeshLoadOptions options{scene.up, scene.allow_outside, &local, scene.crease_angle_deg};
  Mesh mesh;
  try {
    mesh = loadMesh(scene.mesh, options);
  } catch (const InputError& e) {
    if (fromSceneFile) throw InputError(scene.origin.file, "mesh", e.what());
    throw;
  }
  for (auto& w : local) {
    if (fromSceneFile) w = scene.origin.file + ": mesh: " + w;
    if (warnings) warnings->push_back(std::move(w));
    else std::cerr << "warning: " << printable(w, kMessageLineLimit) << "\n";
  }
  return mesh;
}

}  // namespace marble
