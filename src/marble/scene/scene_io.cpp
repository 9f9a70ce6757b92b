// A scene as JSON, both ways, in one place: each part of the scene (camera, light, render
// settings) has its reader and its writer side by side, so a field is added to both at once.
// The writer emits every field, floats as the shortest decimal that reads back bit for bit, and
// files relative to the scene's folder; loadSceneText(sceneToJsonText(s)) == s.
#include "marble/scene/scene_io.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/core/input_file.h"
#include "marble/core/json_limits.h"
#include "marble/scene/enum_choice.h"
#include "marble/scene/json_object_reader.h"
#include "marble/scene/material_io.h"

namespace marble {
namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

// ---- values

// The shortest decimal that reads back (through double, as the JSON reader stores it) as `f`.
ojson number(float f) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, f);
  if (ec == std::errc()) {
    const double d = std::strtod(std::string(buf, end).c_str(), nullptr);
    if (static_cast<float>(d) == f) return d;
  }
  return static_cast<double>(f);
}

ojson vec3(const glm::vec3& v) { return ojson::array({number(v.x), number(v.y), number(v.z)}); }

// ---- files named in a scene: relative to the scene's folder

// A path written in a scene file is relative to the scene's folder.
std::string resolveAgainstScene(const std::filesystem::path& scenePath, const std::string& written) {
  std::filesystem::path p(written);
  if (p.is_relative()) p = scenePath.parent_path() / p;
  return p.lexically_normal().string();
}

// loadScene resolves a relative path (mesh, environment map) against the scene file's folder.
std::string fileField(const std::string& file, const std::filesystem::path& scenePath) {
  std::error_code ec;
  const auto folder = std::filesystem::absolute(scenePath, ec).parent_path();
  const auto absFile = std::filesystem::absolute(file, ec);
  const auto rel = std::filesystem::proximate(absFile, folder, ec);
  return (ec || rel.empty()) ? absFile.string() : rel.generic_string();
}

std::string meshField(const std::string& mesh, const std::filesystem::path& scenePath) {
  return mesh.rfind("builtin:", 0) == 0 ? mesh : fileField(mesh, scenePath);
}

// ---- camera

void readCamera(const json& j, const std::string& file, Camera& cam, std::vector<std::string>& warnings) {
  JsonObjectReader r(j, file, "camera.", JsonWording::Scene);
  r.vec3("position", cam.position, -1e4f, 1e4f);
  r.vec3("target", cam.target, -1e4f, 1e4f);
  r.vec3("up", cam.up, -1e4f, 1e4f);
  r.number("fov_y_deg", cam.fov_y_deg, 1.0f, 179.0f);
  if (glm::length(cam.up) < 1e-6f) r.fail("up", "must not be the zero vector");
  if (glm::length(cam.position - cam.target) < 1e-6f) r.fail("position", "must differ from camera.target");
  if (glm::length(glm::cross(glm::normalize(cam.position - cam.target), glm::normalize(cam.up))) < 1e-4f)
    r.fail("up", "must not be parallel to the viewing direction");
  r.warnUnknown(warnings);
}

ojson writeCamera(const Camera& cam) {
  return {{"position", vec3(cam.position)},
          {"target", vec3(cam.target)},
          {"up", vec3(cam.up)},
          {"fov_y_deg", number(cam.fov_y_deg)}};
}

// ---- light

void readLight(const json& j, const std::string& file, Light& light, std::vector<std::string>& warnings) {
  JsonObjectReader r(j, file, "light.", JsonWording::Scene);
  std::string type;
  if (r.string("type", type)) {
    const EnumChoice* e = findChoice(lightTypeChoices(), type);
    if (!e) r.fail("type", "expected " + choiceAlternatives(lightTypeChoices()) + ", got \"" + type + "\"");
    light.type = static_cast<LightType>(e->value);
  }
  r.vec3("position", light.position, -1e4f, 1e4f);
  r.vec3("color", light.color, 0.0f, 1e3f);
  r.number("intensity", light.intensity, 0.0f, 1e4f);
  if (glm::length(light.position) < 1e-3f) r.fail("position", "must not be at the origin (the object is there)");
  r.warnUnknown(warnings);
}

ojson writeLight(const Light& light) {
  return {{"type", choiceName(lightTypeChoices(), static_cast<int>(light.type))},
          {"position", vec3(light.position)},
          {"color", vec3(light.color)},
          {"intensity", number(light.intensity)}};
}

// ---- render settings

void readRender(const json& j, const std::filesystem::path& scenePath, RenderSettings& rs,
                std::vector<std::string>& warnings) {
  JsonObjectReader r(j, scenePath.string(), "render.", JsonWording::Scene);
  r.integer("width", rs.width, 1, kMaxRenderSize);
  r.integer("height", rs.height, 1, kMaxRenderSize);
  r.vec3("background", rs.background, 0.0f, 1.0f);
  r.number("exposure", rs.exposure, -10.0f, 10.0f);
  std::string env;
  const bool envGiven = r.string("environment", env);
  if (envGiven) {
    try {
      rs.environment = parseEnvironment(env);
    } catch (const std::invalid_argument& e) {
      r.fail("environment", e.what());
    }
  }
  r.number("environment_intensity", rs.environment_intensity, 0.0f, 100.0f);
  std::string sssRes;
  if (r.string("subsurface_resolution", sssRes)) {
    const EnumChoice* e = findChoice(subsurfaceResolutionChoices(), sssRes);
    if (!e)
      r.fail("subsurface_resolution",
             "expected " + choiceAlternatives(subsurfaceResolutionChoices()) + ", got \"" + sssRes + "\"");
    rs.subsurface_resolution = static_cast<SubsurfaceResolution>(e->value);
  }
  std::string antialias;
  if (r.string("antialias", antialias)) {
    try {
      rs.antialias = parseAntialias(antialias);
    } catch (const std::invalid_argument& e) {
      r.fail("antialias", e.what());
    }
  }
  std::string map;
  if (r.string("environment_map", map)) {
    if (map.empty()) r.fail("environment_map", "must not be empty");
    rs.environment_map = resolveAgainstScene(scenePath, map);
    if (!envGiven) rs.environment = Environment::Map;  // naming a map is asking for it
  }
  if (rs.environment == Environment::Map && rs.environment_map.empty())
    r.fail("environment", "\"map\" needs render.environment_map (an equirectangular .hdr file)");
  r.number("environment_rotation_deg", rs.environment_rotation_deg, -360.0f, 360.0f);
  r.boolean("backdrop", rs.backdrop);
  r.number("backdrop_blur", rs.backdrop_blur, 0.0f, 1.0f);
  r.boolean("ground", rs.ground);
  std::string mode;
  if (r.string("mode", mode)) {
    try {
      rs.mode = parseRenderMode(mode);
    } catch (const std::invalid_argument& e) {
      r.fail("mode", e.what());
    }
  }
  r.warnUnknown(warnings);
}

ojson writeRender(const RenderSettings& r, const std::filesystem::path& scenePath) {
  ojson j = {{"width", r.width},
             {"height", r.height},
             {"background", vec3(r.background)},
             {"mode", renderModeName(r.mode)},
             {"exposure", number(r.exposure)},
             {"environment", choiceName(environmentChoices(), static_cast<int>(r.environment))},
             {"environment_intensity", number(r.environment_intensity)},
             {"subsurface_resolution", choiceName(subsurfaceResolutionChoices(), static_cast<int>(r.subsurface_resolution))},
             {"antialias", antialiasName(r.antialias)}};
  // The map is kept while another environment is chosen, so switching back finds it.
  if (!r.environment_map.empty()) j["environment_map"] = fileField(r.environment_map, scenePath);
  j["environment_rotation_deg"] = number(r.environment_rotation_deg);
  j["backdrop"] = r.backdrop;
  j["backdrop_blur"] = number(r.backdrop_blur);
  j["ground"] = r.ground;
  return j;
}

std::string readText(const std::filesystem::path& path) {
  // A regular file only (a FIFO or /dev/zero would never end), and not absurdly large.
  InputFile in(path, path.string(), "a file");
  if (in.size() > (64u << 20)) throw InputError(path.string(), "", "is larger than 64 MiB; not a scene");
  return in.readAll(64u << 20);
}

}  // namespace

Scene loadScene(const std::filesystem::path& path, std::vector<std::string>& warnings) {
  return loadSceneText(readText(path), path, warnings);
}

Scene loadSceneText(const std::string& text, const std::filesystem::path& path, std::vector<std::string>& warnings) {
  const std::string file = path.string();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(file, "", "empty file");
  checkJsonNesting(text, file);
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for numbers like 1e400
    // nlohmann's message carries line and column: "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    throw InputError(file, "", "invalid JSON: " + jsonErrorText(e.what()));
  }
  if (!root.is_object()) throw InputError(file, "", "expected a JSON object at the top level");

  Scene scene;
  JsonObjectReader r(root, file, "", JsonWording::Scene);
  std::string mesh;
  if (r.string("mesh", mesh)) {
    if (mesh.empty()) r.fail("mesh", "must not be empty");
    scene.mesh = mesh.rfind("builtin:", 0) == 0 ? mesh : resolveAgainstScene(path, mesh);
  }
  std::string up;
  if (r.string("up", up)) {
    try {
      scene.up = parseUpAxis(up);
    } catch (const std::invalid_argument&) {
      r.fail("up", "expected one of \"y\", \"z\", \"x\", \"-y\", \"-z\", \"-x\", got \"" + up + "\"");
    }
  }
  r.number("crease_angle_deg", scene.crease_angle_deg, 0.0f, 180.0f);
  r.boolean("allow_outside", scene.allow_outside);
  r.number("mm_per_unit", scene.mm_per_unit, 1e-3f, 1e6f);
  if (const json* c = r.object("camera")) readCamera(*c, file, scene.camera, warnings);
  if (const json* l = r.object("light")) readLight(*l, file, scene.light, warnings);
  if (const json* m = r.object("material")) applyMaterialJson(scene.material, *m, file, "material.", warnings);
  if (const json* rs = r.object("render")) readRender(*rs, path, scene.render, warnings);
  r.warnUnknown(warnings);
  scene.origin = SceneOrigin{file, scene.mesh, scene.render.environment_map};
  return scene;
}

std::string sceneToJsonText(const Scene& scene, const std::filesystem::path& path) {
  ojson j;
  j["mesh"] = meshField(scene.mesh, path);
  j["up"] = std::string(upAxisName(scene.up));
  j["mm_per_unit"] = number(scene.mm_per_unit);
  j["crease_angle_deg"] = number(scene.crease_angle_deg);
  if (scene.allow_outside) j["allow_outside"] = true;
  j["camera"] = writeCamera(scene.camera);
  j["light"] = writeLight(scene.light);
  // materialToJson sorts its keys; re-order them as preset files have them.
  const nlohmann::json m = materialToJson(scene.material);
  ojson mat = ojson::object();
  for (const auto& key : materialKeys())
    if (m.contains(key)) mat[key] = ojson::parse(m[key].dump());
  j["material"] = mat;
  j["render"] = writeRender(scene.render, path);
  return j.dump(2) + "\n";
}

void saveScene(const std::filesystem::path& path, const Scene& scene) {
  writeFileAtomically(path, sceneToJsonText(scene, path));
}

}  // namespace marble
