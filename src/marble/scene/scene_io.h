#pragma once
// A scene as JSON, both ways (scene_io.cpp; loadScene and loadSceneText are declared in
// scene.h). Writing a whole scene as JSON that loadScene reads back to the same Scene:
// every field is written (the full material, not a preset name plus overrides), floats as the
// shortest decimal that reads back bit for bit, and the mesh path relative to the scene file's
// folder so a scene and its mesh can be moved together.
#include <filesystem>
#include <string>

#include "marble/scene/scene.h"

namespace marble {

// The JSON text of `scene` as it would be saved at `path` (the path only matters for making
// the mesh path relative). Keys in a fixed, readable order.
std::string sceneToJsonText(const Scene& scene, const std::filesystem::path& path);

// The keyword of the PNG text chunk in which `marble render` stores the scene of a picture
// (sceneToJsonText relative to the PNG), so that the PNG can be given as a scene.
inline constexpr const char* kPngSceneKeyword = "marble.scene";

// Writes the scene atomically (an existing file survives a failed write). Throws InputError.
void saveScene(const std::filesystem::path& path, const Scene& scene);

}  // namespace marble
