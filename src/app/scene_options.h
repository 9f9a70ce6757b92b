#pragma once
// Options shared by the commands that render a scene (render, view, bench): the input, and
// what the command line overrides in it.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "marble/scene/placement.h"
#include "marble/scene/scene.h"

namespace marble {

struct SceneOptions {
  std::string input;               // SCENE.json, a mesh file, or empty for the default scene
  int width = 0, height = 0;       // 0 = the scene's
  std::string mode;                // render mode name, empty = the scene's
  std::string preset;              // material preset, empty = the scene's
  std::vector<std::string> sets;   // key=value material overrides
  std::string up;                  // up axis of the mesh file
  std::optional<float> creaseAngle;  // degrees; hard edges for computed normals
  std::string subsurfaceResolution;  // "half" | "full", empty = the scene's
  std::string antialias;           // "fxaa" or "none", empty = the scene's
  std::string environment;         // studio, none or map; empty = the scene's
  std::string environmentMap;      // a .hdr (relative to the working folder); implies "map"
  std::optional<float> environmentRotation;  // degrees about +Y
  std::optional<float> environmentIntensity;
  // Look-dev (issue 19): light, camera, size and stage without writing JSON.
  std::string light;               // front | side | back | top | AZ,EL (degrees, about the camera's azimuth)
  std::string lightPosition;       // X,Y,Z
  std::string camera;              // AZ,EL[,DIST] about the camera's target
  std::string cameraPosition;      // X,Y,Z
  std::optional<float> sizeMm;     // the object's largest extent in mm (mm_per_unit = size / 2)
  std::optional<float> exposure;   // stops
  std::string background;          // R,G,B in [0, 1], as displayed
  std::string backdrop;            // on | off: the environment seen behind the object
  std::optional<float> backdropBlur;
  std::string ground;              // on | off: a floor with the object's shadow
  // Without an input: the showcase scene (render, view) or the fixed built-in Scene{} (bench,
  // whose figures must stay comparable).
  bool showcaseWhenEmpty = true;
  bool allowOutside = false;       // glTF buffers may come from outside the glTF's folder
};

void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool withSize);
// --allow-outside alone (part of addSceneOptions), for commands that take fewer scene options.
void addAllowOutsideFlag(CLI::App& cmd, SceneOptions& o);

// Loads the scene and applies the overrides; warnings go to stderr. Throws InputError.
Scene buildScene(const SceneOptions& o);
// The warning for `--set key=...` when `mode` does not read `key` (naming the key, the mode and
// the modes that do) or `m`'s other values leave it unused (a vein-model key with vein_model
// "paper"); empty when it is used, or for keys no mode reads (name, description).
std::string ignoredKeyWarning(const std::string& key, const Material& m, RenderMode mode);

// Runs `body`, turning errors into one line on stderr and an exit code:
// InputError -> 2, EnvironmentError -> 1, anything else -> 1.
int reportErrors(const char* command, const std::function<int()>& body);

}  // namespace marble
