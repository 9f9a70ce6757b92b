#pragma once
// A scene: which mesh, seen from where, lit how, made of which marble, rendered how.
// Every field is optional in the JSON file (docs/scene-format.md lists the defaults).
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "marble/mesh/mesh.h"
#include "marble/scene/material.h"

namespace marble {

struct Camera {
  glm::vec3 position{0.0f, 0.8f, 4.2f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 40.0f;
  bool operator==(const Camera&) const = default;
};

enum class LightType { Point, Directional };

struct Light {
  LightType type = LightType::Point;
  glm::vec3 position{3.0f, 3.0f, 3.0f};  // for a directional light: the direction it comes from
  glm::vec3 color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;
  bool operator==(const Light&) const = default;
};

// The render modes, by their exact command-line names (issue 4).
enum class RenderMode {
  Paper, Marble, Phong, OrenNayar, Subsurface, Reflectance, Albedo, LightDepth, Thickness, Depth, Position,
  Normal, Floor
};
const std::vector<std::string>& renderModeNames();  // in enum order
RenderMode parseRenderMode(const std::string& name);  // throws std::invalid_argument
const std::string& renderModeName(RenderMode mode);
// Whether the mode's picture contains the marble pattern's colour (the shading modes and
// `albedo`); the views of buffers (light depth, thickness, depth, position, normal) and `floor`
// do not, so the pattern is not evaluated for them.
bool modeShowsAlbedo(RenderMode mode);

// Light from around the object (`marble` mode): the built-in procedural studio, nothing, or an
// equirectangular Radiance .hdr file.
enum class Environment { Studio, None, Map };
const std::vector<std::string>& environmentNames();  // in enum order: studio, none, map
Environment parseEnvironment(const std::string& name);  // throws std::invalid_argument

// Where the `marble` mode's subsurface blur runs: at half resolution (a quarter of the pixels;
// fast, for interaction) or at full resolution (slightly crisper, for final images).
enum class SubsurfaceResolution { Half, Full };  // "half" | "full"

// Antialiasing of the final picture (issue 5): FXAA after the post pass, or none.
enum class Antialias { None, Fxaa };
Antialias parseAntialias(const std::string& name);  // "none" | "fxaa"; throws std::invalid_argument
const char* antialiasName(Antialias aa);

struct RenderSettings {
  int width = 800;
  int height = 800;
  glm::vec3 background{0.19f, 0.11f, 0.03f};  // the paper's dark brown, as displayed
  RenderMode mode = RenderMode::Marble;
  float exposure = 0.0f;                      // stops, for the `marble` mode's tone mapping
  Environment environment = Environment::Studio;
  float environment_intensity = 0.6f;
  SubsurfaceResolution subsurface_resolution = SubsurfaceResolution::Half;
  Antialias antialias = Antialias::Fxaa;      // not for `floor` (a benchmark baseline)
  std::string environment_map;                // the .hdr (resolved against the scene's folder); used when Map
  float environment_rotation_deg = 0.0f;      // turns the map about +Y (yaw)
  // The stage (`marble` only; render/stage_pass.h): the environment seen behind the object
  // instead of `background`, blurred by a GGX roughness; a floor under the object with its shadow.
  bool backdrop = false;
  float backdrop_blur = 0.3f;                 // 0 sharp .. 1 very blurred
  bool ground = false;
  bool operator==(const RenderSettings&) const = default;
};

// Where a scene was read from, so that an error in a file it names says so
// ("scene.json: mesh: model.obj: line 3: ..."). It is not part of what the scene is: the same
// scene read from two files compares equal.
struct SceneOrigin {
  std::string file;            // the scene file; empty when the scene did not come from one
  std::string mesh;            // Scene::mesh and render.environment_map as that file gave them, so
  std::string environmentMap;  // that a value the command line replaced is not blamed on the file
  bool operator==(const SceneOrigin&) const { return true; }
};

struct Scene {
  std::string mesh = "builtin:sculpture";  // a path (relative to the scene file) or builtin:NAME
  // glTF buffers may be read from outside the glTF's folder ("allow_outside" in a scene file,
  // --allow-outside on the command line; docs/reliability.md, "What a file may pull in").
  bool allow_outside = false;
  UpAxis up = UpAxis::Y;
  // Real size: millimetres per scene unit. The normalized mesh is 2 units across, so the
  // default 100 makes it a 20 cm statuette. Scattering lengths are in millimetres.
  float mm_per_unit = 100.0f;
  Camera camera;
  Light light;
  Material material;
  RenderSettings render;
  SceneOrigin origin;
  bool operator==(const Scene&) const = default;
};

// Limits on what a scene may ask for.
constexpr int kMaxRenderSize = 8192;

// Reads and validates a scene file. Wrong types and out-of-range values throw InputError
// naming the file and the field ("scene.json: camera.fov_y_deg: expected a number in
// (1, 179), got 500"); unknown keys are appended to `warnings`.
Scene loadScene(const std::filesystem::path& path, std::vector<std::string>& warnings);
// The same for scene JSON already read (`path` names it in messages; relative paths are
// resolved against its folder).
Scene loadSceneText(const std::string& text, const std::filesystem::path& path, std::vector<std::string>& warnings);

// Interprets a command-line input: a .json scene, a PNG written by `marble render` (the scene
// it carries), a mesh file (default scene around it), or empty (the built-in default scene).
Scene sceneForInput(const std::string& input, std::vector<std::string>& warnings);

// Resolves Scene::mesh and loads it (builtin:NAME or a file). An error in a mesh the scene file
// named is reported as "<scene file>: mesh: <the mesh's error>"; warnings are appended to
// `warnings` when given, else printed to stderr.
Mesh loadSceneMesh(const Scene& scene, std::vector<std::string>* warnings = nullptr);

}  // namespace marble
