#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/scene/scene_io.h"
#include "marble/core/input_file.h"
#include "marble/core/json_limits.h"
#include "marble/scene/enum_choice.h"
#include "marble/scene/material_io.h"
#include "marble/scene/scene.h"

namespace marble {
namespace {

using json = nlohmann::json;

// Reads fields of one JSON object, checking types and ranges and remembering which keys
// were used, so the leftovers can be reported as unknown.
class ObjectReader {
public:
  ObjectReader(const json& obj, std::string file, std::string prefix)
      : obj_(obj), file_(std::move(file)), prefix_(std::move(prefix)) {}

  const json* find(const std::string& key) {
    used_.push_back(key);
    auto it = obj_.find(key);
    return it == obj_.end() ? nullptr : &*it;
  }

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(file_, prefix_ + key, problem);
  }

  static std::string describe(const json& v) { return std::string(v.type_name()) + " " + jsonExcerpt(v); }

  void number(const std::string& key, float& out, float lo, float hi) {
    const json* v = find(key);
    if (!v) return;
    if (!v->is_number()) fail(key, "expected a number, got " + describe(*v));
    const double d = v->get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
      fail(key, "expected a number in [" + fmt(lo) + ", " + fmt(hi) + "], got " + jsonExcerpt(*v));
    out = static_cast<float>(d);
  }

  void integer(const std::string& key, int& out, int lo, int hi) {
    const json* v = find(key);
    if (!v) return;
    if (!v->is_number_integer()) fail(key, "expected a whole number, got " + describe(*v));
    const long long i = v->get<long long>();
    if (i < lo || i > hi) fail(key, "expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + jsonExcerpt(*v));
    out = static_cast<int>(i);
  }

  void vec3(const std::string& key, glm::vec3& out, float lo, float hi) {
    const json* v = find(key);
    if (!v) return;
    if (!v->is_array() || v->size() != 3) fail(key, "expected an array of 3 numbers, got " + describe(*v));
    glm::vec3 r;
    for (int i = 0; i < 3; ++i) {
      const json& c = (*v)[static_cast<size_t>(i)];
      if (!c.is_number()) fail(key, "expected an array of 3 numbers, got " + describe(*v));
      const double d = c.get<double>();
      if (!std::isfinite(d) || d < lo || d > hi)
        fail(key, "component " + std::to_string(i) + " must be in [" + fmt(lo) + ", " + fmt(hi) + "], got " + jsonExcerpt(c));
      r[i] = static_cast<float>(d);
    }
    out = r;
  }

  void boolean(const std::string& key, bool& out) {
    const json* v = find(key);
    if (!v) return;
    if (!v->is_boolean()) fail(key, "expected true or false, got " + describe(*v));
    out = v->get<bool>();
  }

  bool string(const std::string& key, std::string& out) {
    const json* v = find(key);
    if (!v) return false;
    if (!v->is_string()) fail(key, "expected a string, got " + describe(*v));
    out = v->get<std::string>();
    return true;
  }

  const json* object(const std::string& key) {
    const json* v = find(key);
    if (v && !v->is_object()) fail(key, "expected an object, got " + describe(*v));
    return v;
  }

  void warnUnknown(std::vector<std::string>& warnings) const {
    for (auto it = obj_.begin(); it != obj_.end(); ++it)
      if (std::find(used_.begin(), used_.end(), it.key()) == used_.end())
        warnings.push_back(file_ + ": " + prefix_ + it.key() + ": unknown key (ignored)");
  }

private:
  static std::string fmt(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }
  const json& obj_;
  std::string file_, prefix_;
  std::vector<std::string> used_;
};

void readCamera(const json& j, const std::string& file, Camera& cam, std::vector<std::string>& warnings) {
  ObjectReader r(j, file, "camera.");
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

void readLight(const json& j, const std::string& file, Light& light, std::vector<std::string>& warnings) {
  ObjectReader r(j, file, "light.");
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

// A path written in a scene file is relative to the scene's folder.
std::string resolveAgainstScene(const std::filesystem::path& scenePath, const std::string& written) {
  std::filesystem::path p(written);
  if (p.is_relative()) p = scenePath.parent_path() / p;
  return p.lexically_normal().string();
}

void readRender(const json& j, const std::filesystem::path& scenePath, RenderSettings& rs,
                std::vector<std::string>& warnings) {
  ObjectReader r(j, scenePath.string(), "render.");
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
  ObjectReader r(root, file, "");
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
  if (const json* v = r.find("allow_outside")) {
    if (!v->is_boolean()) r.fail("allow_outside", "expected true or false, got " + ObjectReader::describe(*v));
    scene.allow_outside = v->get<bool>();
  }
  r.number("mm_per_unit", scene.mm_per_unit, 1e-3f, 1e6f);
  if (const json* c = r.object("camera")) readCamera(*c, file, scene.camera, warnings);
  if (const json* l = r.object("light")) readLight(*l, file, scene.light, warnings);
  if (const json* m = r.object("material")) applyMaterialJson(scene.material, *m, file, "material.", warnings);
  if (const json* rs = r.object("render")) readRender(*rs, path, scene.render, warnings);
  r.warnUnknown(warnings);
  scene.origin = SceneOrigin{file, scene.mesh, scene.render.environment_map};
  return scene;
}

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
